#include "oit/approximate/accumulation_targets.hpp"

#include "oit/approximate/approximate_bindings.h"
#include "oit/draw_transparent.hpp"
#include "oit/precision.hpp"

#include <stdexcept>

namespace strata::approximate {

void AccumulationTargets::beginAccumulation(const FrameContext& frame, int precisionBits) {
    if (frame.size != size_ || precisionBits != bits_ || !fbo_) {
        accum_ = gl::createTexture2D(rgbaFloatFormat(precisionBits), frame.size.x, frame.size.y);
        transmittance_ = gl::createTexture2D(redFloatFormat(precisionBits), frame.size.x, frame.size.y);
        fbo_ = gl::Framebuffer::create();
        glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, accum_.id(), 0);
        glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT1, transmittance_.id(), 0);
        const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
        glNamedFramebufferDrawBuffers(fbo_.id(), 2, buffers);
        size_ = frame.size;
        bits_ = precisionBits;
    }
    // The frame targets may have been reallocated since the last frame: attach every time.
    glNamedFramebufferTexture(fbo_.id(), GL_DEPTH_ATTACHMENT, frame.targets.depth(), 0);
    if (glCheckNamedFramebufferStatus(fbo_.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("accumulation framebuffer incomplete");
    const float zero[4] = {0, 0, 0, 0};
    const float one[4] = {1, 1, 1, 1};
    glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, 0, zero);
    glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, 1, one);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    setTransparentDepthState(frame);
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunci(0, GL_ONE, GL_ONE);
    glBlendFunci(1, GL_ZERO, GL_ONE_MINUS_SRC_COLOR);
}

void AccumulationTargets::endAccumulation() const {
    glDisable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ZERO);
    glBindTextureUnit(gpu::BIND_ACCUM, accum_.id());
    glBindTextureUnit(gpu::BIND_TRANSMITTANCE, transmittance_.id());
}

std::uint64_t AccumulationTargets::bytesPerPixel(int precisionBits) {
    return floatTexelBytes(precisionBits, 4) + floatTexelBytes(precisionBits, 1);
}

}  // namespace strata::approximate
