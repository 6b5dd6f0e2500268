#include "oit/fragment_lists.hpp"

#include "common/bindings.h"
#include "gl/debug.hpp"
#include "oit/abuffer_node.h"
#include "oit/draw_transparent.hpp"
#include "oit/node_texels.hpp"

#include <algorithm>
#include <stdexcept>

namespace strata {
namespace {

constexpr std::uint64_t kNodeBytes = sizeof(gpu::FragmentNode);

// Halves the longer side; both halves go on the list.
void splitTile(const FragmentLists::Tile& t, std::vector<FragmentLists::Tile>& out) {
    if (t.size.x >= t.size.y) {
        const int half = t.size.x / 2;
        out.push_back({t.origin, {half, t.size.y}});
        out.push_back({{t.origin.x + half, t.origin.y}, {t.size.x - half, t.size.y}});
    } else {
        const int half = t.size.y / 2;
        out.push_back({t.origin, {t.size.x, half}});
        out.push_back({{t.origin.x, t.origin.y + half}, {t.size.x, t.size.y - half}});
    }
}

}  // namespace

FragmentLists::Run FragmentLists::render(const FrameContext& frame, const SceneProgram& storeProgram,
                                         std::uint64_t initialNodes, double maxBlockMiB,
                                         const std::function<void(const Tile&)>& resolve) {
    if (!counter_) {
        counter_ = gl::Buffer::create();
        glNamedBufferStorage(counter_.id(), sizeof(GLuint), nullptr, GL_DYNAMIC_STORAGE_BIT | GL_MAP_READ_BIT);
    }
    if (frame.size != headsSize_ || headLayers_ != allocatedHeadLayers_) {
        if (headLayers_ > 1) {
            heads_ = gl::createTexture(GL_TEXTURE_2D_ARRAY);
            glTextureStorage3D(heads_.id(), 1, GL_R32UI, frame.size.x, frame.size.y, headLayers_);
        } else {
            heads_ = gl::createTexture2D(GL_R32UI, frame.size.x, frame.size.y);
        }
        headsSize_ = frame.size;
        allocatedHeadLayers_ = headLayers_;
    }
    // The pool also fits the buffer-texture view the resolves read it through (two texels a node).
    const std::uint64_t maxNodes =
        std::max<std::uint64_t>(std::min(gl::storageBlockElements(kNodeBytes, maxBlockMiB), maxNodeTexelNodes()), 1);
    // First frame: the setting, or two fragments per pixel; later frames keep what the previous
    // frame needed, so the pool follows the fragments present.
    if (capacity_ == 0) capacity_ = initialNodes > 0 ? initialNodes : std::uint64_t(frame.size.x) * frame.size.y * 2;
    capacity_ = std::clamp<std::uint64_t>(capacity_, 1, maxNodes);
    ensurePool();

    Run run;
    // Start from last frame's tiles while they are still needed: finding out again that the
    // whole frame overflows would cost a wasted store pass every frame. Back to one tile once
    // last frame's fragments fit in half the largest pool.
    const bool reuseTiles = !lastTiles_.empty() && lastTilesSize_ == frame.size && lastTotal_ * 2 > maxNodes;
    std::vector<Tile> tiles = reuseTiles ? lastTiles_ : std::vector<Tile>{{{0, 0}, frame.size}};
    std::vector<Tile> done;
    while (!tiles.empty()) {
        const Tile tile = tiles.back();
        tiles.pop_back();
        const std::uint64_t needed = store(frame, tile, storeProgram, run);
        if (needed > capacity_) {
            if (needed <= maxNodes) {
                // Grow to what this tile needs (with headroom) and store it again.
                capacity_ = std::min<std::uint64_t>(maxNodes, needed + needed / 8);
                ensurePool();
                ++run.regrows;
                tiles.push_back(tile);
                continue;
            }
            if (tile.size.x * tile.size.y <= 1)
                throw std::runtime_error(label_ + ": one pixel holds " + std::to_string(needed) +
                                         " fragments, more than the largest storage block");
            capacity_ = maxNodes;
            ensurePool();
            splitTile(tile, tiles);
            continue;
        }
        bind();
        resolve(tile);
        run.fragments += needed;
        done.push_back(tile);
    }
    glDisable(GL_SCISSOR_TEST);
    run.tiles = int(done.size());
    // Kept in the order they pop in next frame (tiles are taken from the back).
    lastTiles_.assign(done.rbegin(), done.rend());
    if (lastTiles_.size() == 1) lastTiles_.clear();
    lastTilesSize_ = frame.size;
    lastTotal_ = run.fragments;
    // Memory sized to the fragments present: give back a pool four times larger than needed.
    const std::uint64_t largestTile = done.size() == 1 ? run.fragments : capacity_;
    if (largestTile * 4 < capacity_) capacity_ = std::max<std::uint64_t>(largestTile + largestTile / 8, 1024);
    return run;
}

void FragmentLists::ensurePool() {
    if (poolCapacity_ == capacity_) return;
    gl::allocateBuffer(nodes_, capacity_ * kNodeBytes, GL_DYNAMIC_COPY, (label_ + " node pool").c_str());
    poolCapacity_ = capacity_;
    nodeTexels_ = makeNodeTexels(nodes_.id(), capacity_);  // re-made with the pool
}

void FragmentLists::bind() const {
    glBindImageTexture(gpu::BIND_HEADS, heads_.id(), 0, allocatedHeadLayers_ > 1 ? GL_TRUE : GL_FALSE, 0,
                       GL_READ_WRITE, GL_R32UI);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BIND_NODES, nodes_.id());
    glBindTextureUnit(gpu::BIND_NODE_TEXELS, nodeTexels_.id());
}

std::uint64_t FragmentLists::bytes() const {
    return poolCapacity_ * kNodeBytes + std::uint64_t(headsSize_.x) * std::uint64_t(headsSize_.y) * 4 * std::uint64_t(allocatedHeadLayers_) +
           sizeof(GLuint);
}

// Stores the tile's fragments; returns how many there were (stored or not).
std::uint64_t FragmentLists::store(const FrameContext& frame, const Tile& tile, const SceneProgram& program, Run& run) {
    gl::ScopedPass pass(frame.timer, label_ + " store");
    GLuint zero = 0;
    glClearTexImage(heads_.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    glNamedBufferSubData(counter_.id(), 0, sizeof(GLuint), &zero);
    // The output framebuffer carries the opaque depth; colour writes stay off.
    glBindFramebuffer(GL_FRAMEBUFFER, frame.targets.outputFramebuffer());
    setTransparentDepthState(frame);
    glEnable(GL_SCISSOR_TEST);
    glScissor(tile.origin.x, tile.origin.y, tile.size.x, tile.size.y);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    bind();
    glBindBufferBase(GL_ATOMIC_COUNTER_BUFFER, gpu::BIND_COUNTERS, counter_.id());
    glProgramUniform1ui(program.id(), glGetUniformLocation(program.id(), "uCapacity"),
                        GLuint(std::min<std::uint64_t>(capacity_, 0xFFFFFFFFu)));
    run.objectDraws += drawTransparent(frame, program, frame.transparentOrder);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    // TEXTURE_UPDATE: the heads the store's image atomics wrote are cleared by glClearTexImage
    // before a regrow's or the next tile's store. TEXTURE_FETCH: the resolves read the nodes the
    // store wrote as a storage buffer through a buffer texture (oit/node_texels.hpp).
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT | GL_ATOMIC_COUNTER_BARRIER_BIT |
                    GL_BUFFER_UPDATE_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    ++run.passes;
    return gl::readUint(counter_);
}

}  // namespace strata
