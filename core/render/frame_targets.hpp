#pragma once
// The render targets of one frame: the opaque pass's colour and depth, and the output colour
// the transparency technique composites into (sharing the opaque depth for depth testing).
#include "gl/objects.hpp"

#include <glm/glm.hpp>

namespace strata {

class FrameTargets {
public:
    // (Re)allocates when the size changes; a 1x1 viewport is valid.
    void resize(glm::ivec2 size);
    glm::ivec2 size() const { return size_; }

    GLuint opaqueColor() const { return opaqueColor_.id(); }   // RGBA32F, linear
    GLuint depth() const { return depth_.id(); }               // DEPTH32F, reversed-Z
    GLuint outputColor() const { return outputColor_.id(); }   // RGBA32F, linear
    GLuint opaqueFramebuffer() const { return opaqueFbo_.id(); }
    GLuint outputFramebuffer() const { return outputFbo_.id(); }

    // Core profile needs a bound vertex array even for a full-screen triangle without attributes.
    GLuint emptyVertexArray() const { return emptyVertexArray_.id(); }

    // Output := opaque colour (what a technique composites over).
    void copyOpaqueToOutput() const;

private:
    glm::ivec2 size_{0, 0};
    gl::Texture opaqueColor_, depth_, outputColor_;
    gl::Framebuffer opaqueFbo_, outputFbo_;
    gl::VertexArray emptyVertexArray_;
};

}  // namespace strata
