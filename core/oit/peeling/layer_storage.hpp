#pragma once
// Per-pixel storage of one peeled layer's coincident fragments, for one side (front-to-back) or
// two (dual: front and back layer), shared by f2b-ll, f2b-fab, f2b-kb, dual-ll and dual-fab.
// The shaders are shaders/oit/peeling/layer_storage.glsl (declarations), layer_store.glsl
// (appending) and layer_resolve.frag.glsl (compositing). Nothing is dropped silently: a list
// pool that is too small grows and the caller repeats the pass; a pool at the largest storage
// block, and the bounded forms' K, keep what fits and count the rest.
#include "gl/objects.hpp"
#include "gl/shader_program.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <string>

namespace strata::peeling {

enum class LayerStore {
    List,     // linked lists in a node pool grown to each layer's fragments (robust)
    Fab,      // K entries per pixel and side with a per-pixel counter
    KBuffer,  // K slots per pixel and side claimed in order by compare-and-swap
};

// What one capture pass found in the layer(s).
struct LayerCounts {
    std::uint64_t inLayer = 0;   // fragments in the layer(s), stored or not
    std::uint64_t stored = 0;
    std::uint64_t overflow = 0;  // in the layer but not stored (counted, reported)
    bool repeat = false;         // the pool grew: repeat the pass (nothing of it is used)
};

class LayerStorage {
public:
    LayerStorage(LayerStore kind, std::string label) : kind_(kind), label_(std::move(label)) {}

    gl::Defines defines() const;  // LAYER_LIST, LAYER_FAB or LAYER_KB

    // Once a frame: sizes the storage for `sides` (1 or 2) per pixel. capacity: K of the
    // bounded forms; maxBlockMiB: the lists' largest pool (0: the device's limit).
    void prepare(glm::ivec2 size, int sides, int capacity, double maxBlockMiB);
    // Before a capture pass: empties the storage, zeroes the counters and binds both, and sets
    // the uniforms of `program`.
    void beginPass(GLuint program);
    // After it: reads the counters. A list pool too small for the pass grows (to the largest
    // block at most: then the two sides split it and the rest is counted) and `repeat` is set.
    LayerCounts endPass();
    // Binds the storage and sets `program`'s uniforms for a resolve.
    void bindForResolve(GLuint program) const;
    // Once a frame, after its passes: a list pool four times larger than the frame's largest
    // layer shrinks (memory sized to the fragments present).
    void endFrame();

    std::uint64_t bytes() const;

private:
    void setUniforms(GLuint program) const;
    void bind() const;
    void allocatePool(std::uint64_t nodes);

    LayerStore kind_;
    std::string label_;
    glm::ivec2 size_{0, 0};
    int sides_ = 1, capacity_ = 0;
    gl::Buffer counters_, storage_;
    gl::Texture pixels_;  // list heads or FAB counts, `sides` stacked rows
    std::uint64_t poolNodes_ = 0, maxNodes_ = 0, frameLargest_ = 0;
    std::uint64_t frontLimit_ = 0, backLimit_ = 0;
    bool split_ = false;  // this pass's limits split a pool that cannot grow
};

}  // namespace strata::peeling
