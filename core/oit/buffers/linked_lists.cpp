// Per-pixel linked lists with a fixed node pool (Yang et al. 2010). The same structure as the
// abuffer reference, but the pool is a setting (average nodes per pixel) and never grows:
// what does not fit is counted and dropped, or blended approximately with tail=1.
// `ll-volume` is the same pool with the volumetric resolve of Barta and Kovacs (oit/volume/),
// the paper's own technique: a fixed pool sized by an estimate.
#include "oit/buffers/bounded_buffer.hpp"
#include "oit/technique.hpp"
#include "oit/volume/volume_resolve.hpp"

#include "common/bindings.h"
#include "oit/node_texels.hpp"

#include <memory>
#include <stdexcept>

namespace strata {
namespace {

using namespace buffers;

struct PoolCapacity {
    static constexpr int kMax = 1024;
    static constexpr const char* kHelp = "node pool size as nodes per pixel on average (pool = w*h*capacity)";
};

class LinkedLists final : public BoundedBuffer<PoolCapacity> {
public:
    // volume: the volumetric store and resolve (VOLUME defined in the shaders).
    LinkedLists(TechniqueInfo info, bool volume)
        : BoundedBuffer(std::move(info)), volume_(volume ? std::make_unique<VolumeResolve>() : nullptr) {}

private:
    // The resolves read the pool through its buffer texture where it fits one (as abuffer's:
    // oit/node_fetch.glsl), the storage buffer otherwise.
    static Shaders surfaceShaders() {
        return {"oit/buffers/ll_store.frag.glsl",
                {"common/fullscreen.vert.glsl", "oit/abuffer_resolve.frag.glsl"},
                {{"LIST_TAIL", ""}},
                {},
                true};
    }

    Shaders shaders() const override {
        if (!volume_) return surfaceShaders();
        return {"oit/buffers/ll_store.frag.glsl",
                {"common/fullscreen.vert.glsl", "oit/abuffer_resolve.frag.glsl"},
                {{"LIST_TAIL", ""}, {"VOLUME", ""}},
                {{"VOLUME", ""}},
                true};
    }

    // Without a volume object in the scene: draw as ll (VolumeResolve::needed).
    std::optional<Shaders> lighterShaders(const FrameContext& frame) const override {
        if (volume_ && !VolumeResolve::needed(frame.scene)) return surfaceShaders();
        return std::nullopt;
    }

    GLuint prepareResolve(const FrameContext& frame, GLuint program) override {
        volumeFrame_ = volume_ && VolumeResolve::needed(frame.scene);
        if (!volumeFrame_) return frame.targets.outputFramebuffer();
        volume_->prepare(frame);
        volume_->bind(frame, program);
        return volume_->colorFramebuffer(frame);
    }

    void finishResolve(TechniqueStats& stats) override {
        if (volumeFrame_) volume_->addStats(stats);
    }

    static std::uint64_t poolNodes(const FrameContext& frame, int capacity) {
        return pixelCount(frame) * std::uint64_t(capacity);
    }

    void allocate(const FrameContext& frame, int capacity) override {
        const std::uint64_t pool = poolNodes(frame, capacity);
        if (pool > 0xFFFFFFFEull)
            throw std::runtime_error("ll: node pool of " + std::to_string(pool) + " nodes exceeds 32-bit indices");
        heads_.ensure(frame.size);
        if (nodes_.ensure(pool, kNodeBytes, "ll node pool")) nodeTexels_ = {};
        // A pool larger than a buffer texture can view keeps the storage-buffer resolve.
        if (!nodeTexels_ && pool > 0 && pool <= maxNodeTexelNodes()) nodeTexels_ = makeNodeTexels(nodes_.id(), pool);
    }

    bool nodeTexelsFit() const override { return bool(nodeTexels_); }

    void clear() override { heads_.clear(); }

    void bindStorage() override {
        heads_.bind(gpu::BIND_HEADS);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BIND_NODES, nodes_.id());
        glBindTextureUnit(gpu::BIND_NODE_TEXELS, nodeTexels_ ? nodeTexels_.id() : 0);
    }

    void setUniforms(GLuint program, const FrameContext& frame, int capacity) const override {
        glProgramUniform1ui(program, glGetUniformLocation(program, "uCapacity"), GLuint(poolNodes(frame, capacity)));
    }

    // The counter keeps running past the pool: it is the number of fragments that arrived.
    StoreCounts counts(const std::array<std::uint32_t, 4>& c, const FrameContext& frame, int capacity) const override {
        const std::uint64_t pool = poolNodes(frame, capacity), arrived = c[0];
        const std::uint64_t overflow = arrived > pool ? arrived - pool : 0;
        return {arrived - overflow, overflow};
    }

    std::uint64_t storageBytes(const FrameContext& frame, int capacity) const override {
        return poolNodes(frame, capacity) * kNodeBytes + pixelCount(frame) * 4 + kCounterBytes;
    }

    PixelImage heads_;
    SizedBuffer nodes_;
    gl::Texture nodeTexels_;  // nodes_ as RGB32UI texels (gpu::BIND_NODE_TEXELS), empty where it does not fit
    std::unique_ptr<VolumeResolve> volume_;  // ll-volume only
    bool volumeFrame_ = false;               // the last frame walked volumes
};

}  // namespace

TechniqueEntry llEntry() {
    TechniqueInfo info{"ll", "buffer", false, true, "2",
                       "w*h*capacity*24 node pool + w*h*4 heads + 16 (+ w*h*20 with tail=1, w*h*10 with tail=1 precision=16)",
                       "per-pixel linked lists: head-pointer image, one global atomic counter, a fixed node pool "
                       "(capacity nodes per pixel on average, never grown); overflow counted and dropped or blended "
                       "approximately (tail=1); resolve sorts by (depth, object, primitive)"};
    info.rgbTransmittance = true;
    return techniqueEntry<LinkedLists>(info, false);
}

TechniqueEntry llVolumeEntry() {
    TechniqueInfo info{"ll-volume", "volumetric", false, true, "2",
                       "as ll, + 24 B per object (medium table)",
                       "the volumetric linked-list resolve (Barta and Kovacs): ll's fixed pool, each list sorted and "
                       "walked through the media of the closed volume objects it crosses (tau, albedo, Rayleigh "
                       "in-scattering), thin surfaces composited in the same walk (coloured filters per channel); overflow counted"};
    info.rgbTransmittance = true;
    return techniqueEntry<LinkedLists>(info, true);
}

}  // namespace strata
