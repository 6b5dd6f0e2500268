#pragma once
// A colour target of the frame's size that shares the frame's opaque depth, for passes that
// must not write the RGBA32F output directly (the floor's R8, blend's RGBA16F at precision=16).
#include "gl/objects.hpp"
#include "render/frame_targets.hpp"

#include <glm/glm.hpp>

namespace strata {

class ScratchTarget {
public:
    // (Re)allocates the colour texture when the size or format changes, attaches the frame's
    // depth (the frame targets may have been reallocated since the last frame), checks
    // completeness (throws std::runtime_error naming `what`) and returns the framebuffer.
    GLuint bind(const FrameTargets& targets, glm::ivec2 size, GLenum format, const char* what);

private:
    gl::Texture color_;
    gl::Framebuffer fbo_;
    glm::ivec2 size_{0, 0};
    GLenum format_ = 0;
};

}  // namespace strata
