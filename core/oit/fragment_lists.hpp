#pragma once
// The exact per-pixel linked lists that abuffer, abuffer-volume and the coplanarity detector
// share: a heads image, one node pool grown to the fragments counted, and the frame split into
// screen tiles where the fragments exceed the largest storage block. A store pass counts every
// fragment (the counter keeps running past the pool); a tile that did not fit grows the pool and
// is stored again, or, past the largest block, is split in two. Nothing is dropped: each tile
// that fits is handed to the owner's resolve before the next is stored.
#include "oit/technique.hpp"
#include "render/scene_program.hpp"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace strata {

class FragmentLists {
public:
    struct Tile {
        glm::ivec2 origin;
        glm::ivec2 size;
    };
    // What one frame's stores did.
    struct Run {
        std::uint64_t fragments = 0;  // stored and resolved, over all tiles
        int passes = 0;               // store passes, regrows included
        int tiles = 0;
        int regrows = 0;
        std::uint64_t objectDraws = 0;
    };

    // `label` names the pool in allocation errors and the store pass ("<label> store").
    explicit FragmentLists(std::string label) : label_(std::move(label)) {}

    // Stores the frame's transparent fragments with `storeProgram` (shaders/oit/abuffer_store or a
    // variant; its uCapacity uniform is set here), tile by tile, calling resolve(tile) with the
    // lists bound for each tile that fit. initialNodes: the pool on the first frame (0: two per
    // pixel); maxBlockMiB: the largest pool (0: the device's storage block limit).
    Run render(const FrameContext& frame, const SceneProgram& storeProgram, std::uint64_t initialNodes,
               double maxBlockMiB, const std::function<void(const Tile&)>& resolve);

    // Heads per pixel (default 1): with more, the heads are a 2D array image of that many layers
    // (bun-ll: one list per depth bucket; shaders declare HEADS_ARRAY). Takes effect next render.
    void setHeadLayers(int layers) { headLayers_ = layers; }

    // Binds the heads image and the node pool for a resolve.
    void bind() const;
    // Pool, heads and counter.
    std::uint64_t bytes() const;

private:
    std::uint64_t store(const FrameContext& frame, const Tile& tile, const SceneProgram& program, Run& run);
    void ensurePool();

    std::string label_;
    gl::Buffer counter_, nodes_;
    gl::Texture nodeTexels_;  // nodes_ as a buffer texture (gpu::BIND_NODE_TEXELS)
    gl::Texture heads_;
    glm::ivec2 headsSize_{0, 0};
    int headLayers_ = 1, allocatedHeadLayers_ = 0;
    std::uint64_t capacity_ = 0, poolCapacity_ = 0;
    std::vector<Tile> lastTiles_;  // last frame's tiles when it needed more than one
    glm::ivec2 lastTilesSize_{0, 0};
    std::uint64_t lastTotal_ = 0;
};

}  // namespace strata
