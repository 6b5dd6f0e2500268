#include "oit/node_texels.hpp"

#include "oit/abuffer_node.h"

#include <algorithm>

namespace strata {

std::uint64_t maxNodeTexelNodes() {
    static const std::uint64_t nodes = [] {
        GLint texels = 0;
        glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &texels);
        return std::uint64_t(std::max<GLint>(texels, 0)) / 2;
    }();
    return nodes;
}

gl::Texture makeNodeTexels(GLuint pool, std::uint64_t nodes) {
    gl::Texture view = gl::createTexture(GL_TEXTURE_BUFFER);
    glTextureBufferRange(view.id(), GL_RGB32UI, pool, 0, GLsizeiptr(nodes * sizeof(gpu::FragmentNode)));
    return view;
}

}  // namespace strata
