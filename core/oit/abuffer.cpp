// `abuffer`, the exact reference: every transparent fragment in front of the opaque depth goes
// into a per-pixel linked list, each list is sorted by (depth, object id, primitive id) and
// composited. Memory is grown to the counted fragments and the frame re-rendered until nothing
// overflows; where the fragments exceed the largest storage block the device allows, the frame
// is rendered in screen tiles, each within the limit. Nothing is ever dropped silently.
// `abuffer-volume` is the same storage with the volumetric resolve (oit/volume/): closed
// objects with a volume material render as media, exactly, with no capacity to choose.
#include "oit/technique.hpp"

#include "common/bindings.h"
#include "gl/debug.hpp"
#include "oit/abuffer_node.h"
#include "oit/draw_transparent.hpp"
#include "oit/volume/volume_resolve.hpp"

#include <algorithm>
#include <memory>
#include <stdexcept>

namespace strata {
namespace {

constexpr std::uint64_t kNodeBytes = sizeof(gpu::FragmentNode);

struct Tile {
    glm::ivec2 origin;
    glm::ivec2 size;
};

struct ABufferSettings {
    int initialNodes = 0;
    double maxBlockMiB = 0;
    bool computeResolve = false;
    static const SettingsSchema<ABufferSettings>& schema() {
        static const SettingsSchema<ABufferSettings> s{
            integerSetting(&ABufferSettings::initialNodes, "initial_nodes", 0, 1000000000, SettingChange::Reallocate,
                           "node pool capacity on the first frame (0: two per pixel); it grows as needed"),
            realSetting(&ABufferSettings::maxBlockMiB, "max_block_mib", 0, 1e6, SettingChange::Reallocate,
                        "largest node pool in MiB (0: the device's GL_MAX_SHADER_STORAGE_BLOCK_SIZE)"),
            flagSetting(&ABufferSettings::computeResolve, "compute_resolve", SettingChange::Nothing,
                        "resolve in a compute dispatch instead of a full-screen fragment pass (same image)"),
        };
        return s;
    }
};

class ABuffer final : public TechniqueWithSettings<ABufferSettings> {
public:
    // volume: the volumetric store and resolve (VOLUME defined in the shaders).
    ABuffer(TechniqueInfo info, bool volume)
        : TechniqueWithSettings(std::move(info)), volume_(volume ? std::make_unique<VolumeResolve>() : nullptr) {}

    void render(const FrameContext& frame) override {
        if (!storeProgram_.program) {
            const gl::Defines defines = volume_ ? gl::Defines{{"VOLUME", ""}} : gl::Defines{};
            storeProgram_ = buildSceneProgram("oit/abuffer_store.frag.glsl", defines);
            resolveProgram_ =
                gl::buildProgram({"common/fullscreen.vert.glsl", "oit/abuffer_resolve.frag.glsl"}, defines);
            computeResolveProgram_ = gl::buildProgram({"oit/abuffer_resolve.comp.glsl"}, defines);
            capacityLocation_ = glGetUniformLocation(storeProgram_.id(), "uCapacity");
            counter_ = gl::Buffer::create();
            glNamedBufferStorage(counter_.id(), sizeof(GLuint), nullptr, GL_DYNAMIC_STORAGE_BIT | GL_MAP_READ_BIT);
        }
        if (frame.size != headsSize_) {
            heads_ = gl::createTexture2D(GL_R32UI, frame.size.x, frame.size.y);
            headsSize_ = frame.size;
        }
        std::uint64_t maxNodes = maxPoolNodes();
        // First frame: the parameter, or two fragments per pixel; later frames keep what the
        // previous frame needed, so the pool follows the fragments present.
        if (capacity_ == 0)
            capacity_ = settings_.initialNodes > 0 ? std::uint64_t(settings_.initialNodes) : std::uint64_t(frame.size.x) * frame.size.y * 2;
        capacity_ = std::max<std::uint64_t>(capacity_, 1);
        if (capacity_ > maxNodes) capacity_ = maxNodes;
        ensurePool();

        stats_ = {};
        if (volume_) volume_->prepare(frame);
        // Start from last frame's tiles while they are still needed: finding out again that the
        // whole frame overflows would cost a wasted store pass every frame. Back to one tile
        // once last frame's fragments fit in half the largest pool.
        const bool reuseTiles = !lastTiles_.empty() && lastTilesSize_ == frame.size && lastTotal_ * 2 > maxNodes;
        std::vector<Tile> tiles = reuseTiles ? lastTiles_ : std::vector<Tile>{{{0, 0}, frame.size}};
        std::vector<Tile> done;
        int tilesDone = 0;
        while (!tiles.empty()) {
            Tile tile = tiles.back();
            tiles.pop_back();
            std::uint64_t needed = store(frame, tile);
            if (needed > capacity_) {
                if (needed <= maxNodes) {
                    // Grow to what this tile needs (with headroom) and render it again.
                    capacity_ = std::min<std::uint64_t>(maxNodes, needed + needed / 8);
                    ensurePool();
                    ++stats_.regrows;
                    tiles.push_back(tile);
                    continue;
                }
                if (tile.size.x * tile.size.y <= 1)
                    throw std::runtime_error("abuffer: one pixel holds " + std::to_string(needed) +
                                             " fragments, more than the largest storage block");
                capacity_ = maxNodes;
                ensurePool();
                splitTile(tile, tiles);
                continue;
            }
            resolve(frame, tile);
            stats_.fragmentsCaptured += needed;
            ++tilesDone;
            done.push_back(tile);
        }
        // Kept in the order they pop in next frame (tiles are taken from the back).
        lastTiles_.assign(done.rbegin(), done.rend());
        if (lastTiles_.size() == 1) lastTiles_.clear();
        lastTilesSize_ = frame.size;
        lastTotal_ = stats_.fragmentsCaptured;
        glDisable(GL_SCISSOR_TEST);
        stats_.tiles = tilesDone;
        stats_.bytes = capacity_ * kNodeBytes + std::uint64_t(frame.size.x) * frame.size.y * 4 + sizeof(GLuint);
        if (volume_) {
            stats_.bytes += volume_->bytes();
            const std::uint64_t ignored = volume_->nestingOverflow();
            stats_.fragmentsDropped += ignored;
            stats_.overflowed = stats_.overflowed || ignored > 0;
        }
        // Memory sized to the fragments present: give back a pool four times larger than needed.
        std::uint64_t largestTile = tilesDone == 1 ? stats_.fragmentsCaptured : capacity_;
        if (largestTile * 4 < capacity_) capacity_ = std::max<std::uint64_t>(largestTile + largestTile / 8, 1024);
    }

private:
    std::uint64_t maxPoolNodes() const { return gl::storageBlockElements(kNodeBytes, settings_.maxBlockMiB); }

    void ensurePool() {
        if (poolCapacity_ == capacity_) return;
        gl::allocateBuffer(nodes_, capacity_ * kNodeBytes, GL_DYNAMIC_COPY, "abuffer node pool");
        poolCapacity_ = capacity_;
    }

    static void splitTile(const Tile& t, std::vector<Tile>& out) {
        if (t.size.x >= t.size.y) {
            int half = t.size.x / 2;
            out.push_back({t.origin, {half, t.size.y}});
            out.push_back({{t.origin.x + half, t.origin.y}, {t.size.x - half, t.size.y}});
        } else {
            int half = t.size.y / 2;
            out.push_back({t.origin, {t.size.x, half}});
            out.push_back({{t.origin.x, t.origin.y + half}, {t.size.x, t.size.y - half}});
        }
    }

    // Stores the tile's fragments; returns how many there were (stored or not).
    std::uint64_t store(const FrameContext& frame, const Tile& tile) {
        gl::ScopedPass pass(frame.timer, info_.id + " store");
        GLuint zero = 0;
        glClearTexImage(heads_.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
        glNamedBufferSubData(counter_.id(), 0, sizeof(GLuint), &zero);
        glBindFramebuffer(GL_FRAMEBUFFER, frame.targets.outputFramebuffer());
        setTransparentDepthState(frame);
        glEnable(GL_SCISSOR_TEST);
        glScissor(tile.origin.x, tile.origin.y, tile.size.x, tile.size.y);
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glBindImageTexture(gpu::BIND_HEADS, heads_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
        glBindBufferBase(GL_ATOMIC_COUNTER_BUFFER, gpu::BIND_COUNTERS, counter_.id());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BIND_NODES, nodes_.id());
        glProgramUniform1ui(storeProgram_.id(), capacityLocation_, GLuint(std::min<std::uint64_t>(capacity_, 0xFFFFFFFFu)));
        stats_.objectDraws += drawTransparent(frame, storeProgram_, frame.transparentOrder);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT |
                        GL_ATOMIC_COUNTER_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
        ++stats_.passes;
        GLuint count = 0;
        glGetNamedBufferSubData(counter_.id(), 0, sizeof(GLuint), &count);
        return count;
    }

    void resolve(const FrameContext& frame, const Tile& tile) {
        if (settings_.computeResolve) {
            resolveCompute(frame, tile);
            return;
        }
        gl::ScopedPass pass(frame.timer, info_.id + " resolve");
        glBindFramebuffer(GL_FRAMEBUFFER,
                          volume_ ? volume_->colorFramebuffer(frame) : frame.targets.outputFramebuffer());
        glEnable(GL_SCISSOR_TEST);
        glScissor(tile.origin.x, tile.origin.y, tile.size.x, tile.size.y);
        glDisable(GL_BLEND);
        glBindImageTexture(gpu::BIND_HEADS, heads_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BIND_NODES, nodes_.id());
        glBindTextureUnit(gpu::BIND_OPAQUE_COLOR, frame.targets.opaqueColor());
        setDepthOrderUniforms(frame, resolveProgram_.id());
        if (volume_) volume_->bind(frame, resolveProgram_.id());
        drawFullscreen(frame, resolveProgram_.id());
        ++stats_.passes;
    }

    void resolveCompute(const FrameContext& frame, const Tile& tile) {
        gl::ScopedPass pass(frame.timer, info_.id + " resolve (compute)");
        const GLuint program = computeResolveProgram_.id();
        glBindImageTexture(gpu::BIND_HEADS, heads_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
        glBindImageTexture(gpu::BIND_RESOLVE_OUTPUT, frame.targets.outputColor(), 0, GL_FALSE, 0, GL_WRITE_ONLY,
                           GL_RGBA32F);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BIND_NODES, nodes_.id());
        glBindTextureUnit(gpu::BIND_OPAQUE_COLOR, frame.targets.opaqueColor());
        setDepthOrderUniforms(frame, program);
        if (volume_) volume_->bind(frame, program);
        glProgramUniform4i(program, glGetUniformLocation(program, "uTile"), tile.origin.x, tile.origin.y, tile.size.x,
                           tile.size.y);
        glUseProgram(program);
        constexpr int group = int(gpu::RESOLVE_GROUP_SIZE);
        glDispatchCompute(GLuint((tile.size.x + group - 1) / group), GLuint((tile.size.y + group - 1) / group), 1);
        // The output is read next as a texture or framebuffer attachment (blit, read-back).
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                        GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        ++stats_.passes;
    }

    SceneProgram storeProgram_;
    gl::Program resolveProgram_, computeResolveProgram_;
    GLint capacityLocation_ = -1;
    gl::Buffer counter_, nodes_;
    gl::Texture heads_;
    glm::ivec2 headsSize_{0, 0};
    std::uint64_t capacity_ = 0, poolCapacity_ = 0;
    std::vector<Tile> lastTiles_;  // last frame's tiles when it needed more than one
    glm::ivec2 lastTilesSize_{0, 0};
    std::uint64_t lastTotal_ = 0;
    std::unique_ptr<VolumeResolve> volume_;  // abuffer-volume only
};

}  // namespace

TechniqueEntry abufferEntry() {
    TechniqueInfo info{"abuffer", "reference", true, true, "2 per tile (+1 store per regrow)",
                       "w*h*4 heads + 24 B per fragment, pool grown to the fragments present",
                       "exact reference: per-pixel linked lists of every fragment, sorted by (depth, object, primitive)"};
    return techniqueEntry<ABuffer>(info, false);
}

TechniqueEntry abufferVolumeEntry() {
    TechniqueInfo info{"abuffer-volume", "volumetric", true, true, "2 per tile (+1 store per regrow)",
                       "as abuffer, + 24 B per object (medium table)",
                       "the exact volumetric reference: abuffer's unbounded lists, resolved through the media of "
                       "closed volume objects (tau, albedo, Rayleigh in-scattering; Barta and Kovacs), other "
                       "transparent objects alpha-composited in the same walk"};
    return techniqueEntry<ABuffer>(info, true);
}

}  // namespace strata
