#pragma once
// A node pool (oit/abuffer_node.h's FragmentNode, 24 bytes) seen as RGB32UI texels, two a node:
// what the list resolves built with NODE_TEXELS read (shaders/oit/node_fetch.glsl), because
// llvmpipe loads a storage buffer lane by lane. Shared by abuffer's FragmentLists and ll's pool.
#include "gl/objects.hpp"

#include <cstdint>

namespace strata {

// The most nodes one view can show: GL_MAX_TEXTURE_BUFFER_SIZE / 2, read on the first call.
std::uint64_t maxNodeTexelNodes();

// A view of the first `nodes` nodes of `pool`; the caller re-makes it whenever the pool is
// reallocated. `nodes` must be within maxNodeTexelNodes().
gl::Texture makeNodeTexels(GLuint pool, std::uint64_t nodes);

}  // namespace strata
