#include "oit/scratch_target.hpp"

#include <stdexcept>
#include <string>

namespace strata {

GLuint ScratchTarget::bind(const FrameTargets& targets, glm::ivec2 size, GLenum format, const char* what) {
    if (size != size_ || format != format_ || !fbo_) {
        color_ = gl::createTexture2D(format, size.x, size.y);
        fbo_ = gl::Framebuffer::create();
        glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, color_.id(), 0);
        size_ = size;
        format_ = format;
    }
    glNamedFramebufferTexture(fbo_.id(), GL_DEPTH_ATTACHMENT, targets.depth(), 0);
    if (glCheckNamedFramebufferStatus(fbo_.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error(std::string(what) + ": scratch framebuffer incomplete");
    return fbo_.id();
}

}  // namespace strata
