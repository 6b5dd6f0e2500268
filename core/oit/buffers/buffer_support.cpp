#include "oit/buffers/buffer_support.hpp"

#include "common/bindings.h"
#include "oit/precision.hpp"

namespace strata::buffers {

void Counters::reset() {
    if (!buffer_) {
        buffer_ = gl::Buffer::create();
        glNamedBufferStorage(buffer_.id(), kCounterBytes, nullptr, GL_DYNAMIC_STORAGE_BIT | GL_MAP_READ_BIT);
    }
    const std::array<std::uint32_t, kCounterSlots> zero{};
    glNamedBufferSubData(buffer_.id(), 0, kCounterBytes, zero.data());
}

void Counters::bind() const { glBindBufferBase(GL_ATOMIC_COUNTER_BUFFER, gpu::BIND_COUNTERS, buffer_.id()); }

std::array<std::uint32_t, kCounterSlots> Counters::read() const {
    std::array<std::uint32_t, kCounterSlots> values{};
    glGetNamedBufferSubData(buffer_.id(), 0, kCounterBytes, values.data());
    return values;
}

std::uint64_t TailTargets::bytesPerPixel() const { return floatTexelBytes(bits_, 4) + floatTexelBytes(bits_, 1); }

void TailTargets::ensure(const FrameContext& frame) {
    if (frame.size == size_ && bits_ == allocatedBits_ && fbo_) {
        // The frame's depth is attached every time: comparing texture names cannot tell a new
        // target from a deleted one whose name GL gave out again.
        glNamedFramebufferTexture(fbo_.id(), GL_DEPTH_ATTACHMENT, frame.targets.depth(), 0);
        return;
    }
    accum_ = gl::createTexture2D(rgbaFloatFormat(bits_), frame.size.x, frame.size.y);
    reveal_ = gl::createTexture2D(redFloatFormat(bits_), frame.size.x, frame.size.y);
    allocatedBits_ = bits_;
    fbo_ = gl::Framebuffer::create();
    glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, accum_.id(), 0);
    glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT1, reveal_.id(), 0);
    glNamedFramebufferTexture(fbo_.id(), GL_DEPTH_ATTACHMENT, frame.targets.depth(), 0);
    const GLenum draw[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glNamedFramebufferDrawBuffers(fbo_.id(), 2, draw);
    size_ = frame.size;
}

void TailTargets::bindForStore(const FrameContext& frame, bool enabled, bool clear) {
    if (!enabled) {
        glBindFramebuffer(GL_FRAMEBUFFER, frame.targets.outputFramebuffer());
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glDisable(GL_BLEND);
        return;
    }
    ensure(frame);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    if (clear) {
        const float zero[4] = {0, 0, 0, 0};
        const float one[4] = {1, 1, 1, 1};
        glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, 0, zero);
        glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, 1, one);
    }
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunci(0, GL_ONE, GL_ONE);                   // sum(a*c, a)
    glBlendFunci(1, GL_ZERO, GL_ONE_MINUS_SRC_COLOR);  // prod(1 - a)
}

void TailTargets::endStore() {
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_BLEND);
}

void TailTargets::bindForResolve(const FrameContext& frame, bool enabled) {
    if (enabled) ensure(frame);
    // Disabled: the shader's uTail is false and never samples; bind the opaque colour so the
    // units hold a complete texture either way.
    glBindTextureUnit(gpu::BIND_TAIL_ACCUM, enabled ? accum_.id() : frame.targets.opaqueColor());
    glBindTextureUnit(gpu::BIND_TAIL_REVEAL, enabled ? reveal_.id() : frame.targets.opaqueColor());
}

void storeBarrier() {
    // TEXTURE_UPDATE: the counts and heads the store's image atomics wrote are cleared by
    // glClearTexImage before the next frame's store.
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT | GL_ATOMIC_COUNTER_BARRIER_BIT |
                    GL_BUFFER_UPDATE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT |
                    GL_TEXTURE_UPDATE_BARRIER_BIT);
}

}  // namespace strata::buffers
