#include "render/frame_targets.hpp"

#include <cstdio>
#include <stdexcept>

namespace strata {
namespace {

// The size is in the message: an incomplete framebuffer here is almost always a size the
// driver could not allocate (checkFrameSize, frame_size.hpp, refuses most of those earlier).
void requireComplete(GLuint fbo, const char* what, glm::ivec2 size) {
    GLenum status = glCheckNamedFramebufferStatus(fbo, GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        char text[160];
        std::snprintf(text, sizeof text, "%s framebuffer of %dx%d incomplete (status 0x%X)", what, size.x, size.y,
                      unsigned(status));
        throw std::runtime_error(text);
    }
}

}  // namespace

void FrameTargets::resize(glm::ivec2 size) {
    if (size.x <= 0 || size.y <= 0) throw std::invalid_argument("frame size must be positive");
    if (size == size_) return;
    size_ = size;
    if (!emptyVertexArray_) emptyVertexArray_ = gl::VertexArray::create();
    // 32-bit float colour keeps the exact reference and the comparisons free of target rounding.
    opaqueColor_ = gl::createTexture2D(GL_RGBA32F, size.x, size.y);
    outputColor_ = gl::createTexture2D(GL_RGBA32F, size.x, size.y);
    depth_ = gl::createTexture2D(GL_DEPTH_COMPONENT32F, size.x, size.y);
    opaqueFbo_ = gl::Framebuffer::create();
    glNamedFramebufferTexture(opaqueFbo_.id(), GL_COLOR_ATTACHMENT0, opaqueColor_.id(), 0);
    glNamedFramebufferTexture(opaqueFbo_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);
    requireComplete(opaqueFbo_.id(), "opaque", size);
    outputFbo_ = gl::Framebuffer::create();
    glNamedFramebufferTexture(outputFbo_.id(), GL_COLOR_ATTACHMENT0, outputColor_.id(), 0);
    glNamedFramebufferTexture(outputFbo_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);
    requireComplete(outputFbo_.id(), "output", size);
}

void FrameTargets::copyOpaqueToOutput() const {
    glCopyImageSubData(opaqueColor_.id(), GL_TEXTURE_2D, 0, 0, 0, 0, outputColor_.id(), GL_TEXTURE_2D, 0, 0, 0, 0,
                       size_.x, size_.y, 1);
}

}  // namespace strata
