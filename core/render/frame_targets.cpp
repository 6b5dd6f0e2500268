#include "render/frame_targets.hpp"

#include <stdexcept>

namespace strata {
namespace {

void requireComplete(GLuint fbo, const char* what) {
    GLenum status = glCheckNamedFramebufferStatus(fbo, GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error(std::string(what) + " framebuffer incomplete (status 0x" +
                                 std::to_string(status) + ")");
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
    requireComplete(opaqueFbo_.id(), "opaque");
    outputFbo_ = gl::Framebuffer::create();
    glNamedFramebufferTexture(outputFbo_.id(), GL_COLOR_ATTACHMENT0, outputColor_.id(), 0);
    glNamedFramebufferTexture(outputFbo_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);
    requireComplete(outputFbo_.id(), "output");
}

void FrameTargets::copyOpaqueToOutput() const {
    glCopyImageSubData(opaqueColor_.id(), GL_TEXTURE_2D, 0, 0, 0, 0, outputColor_.id(), GL_TEXTURE_2D, 0, 0, 0, 0,
                       size_.x, size_.y, 1);
}

}  // namespace strata
