#pragma once
// The two-target accumulation framebuffer wboit and stochastic share: an additive RGBA target
// and a multiplicative transmittance target (revealage), both float at the technique's
// precision (16: RGBA16F + R16F, 10 B per pixel; 32: RGBA32F + R32F, 20 B), depth tested
// against the frame's opaque depth without writing it, then read by a full-screen composite.
#include "oit/technique.hpp"

namespace strata::approximate {

class AccumulationTargets {
public:
    // (Re)allocates on a size or precision change, attaches the frame's opaque depth, clears
    // accumulation to 0 and transmittance to 1, binds the framebuffer and sets the blend state:
    // buffer 0 (ONE, ONE), buffer 1 (ZERO, ONE_MINUS_SRC_COLOR).
    void beginAccumulation(const FrameContext& frame, int precisionBits);
    // Blending off; accumulation and transmittance bound as textures for the composite.
    void endAccumulation() const;

    // Bytes per pixel at a precision: 4 + 1 channels of 2 or 4 bytes.
    static std::uint64_t bytesPerPixel(int precisionBits);

private:
    int bits_ = 0;
    glm::ivec2 size_{0, 0};
    gl::Texture accum_, transmittance_;
    gl::Framebuffer fbo_;
};

}  // namespace strata::approximate
