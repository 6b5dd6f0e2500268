#pragma once
// The two-target accumulation framebuffer wboit and stochastic share: an additive RGBA32F
// target and a multiplicative transmittance target (revealage), depth tested against the
// frame's opaque depth without writing it, then read by a full-screen composite.
#include "oit/technique.hpp"

namespace strata::approximate {

class AccumulationTargets {
public:
    explicit AccumulationTargets(GLenum transmittanceFormat) : transmittanceFormat_(transmittanceFormat) {}

    // (Re)allocates on a size change, attaches the frame's opaque depth, clears accumulation
    // to 0 and transmittance to 1, binds the framebuffer and sets the blend state:
    // buffer 0 (ONE, ONE), buffer 1 (ZERO, ONE_MINUS_SRC_COLOR).
    void beginAccumulation(const FrameContext& frame);
    // Blending off; accumulation and transmittance bound as textures for the composite.
    void endAccumulation() const;

    // Bytes per pixel held: 16 (RGBA32F) + the transmittance format's size.
    std::uint64_t bytesPerPixel() const;

private:
    GLenum transmittanceFormat_;
    glm::ivec2 size_{0, 0};
    gl::Texture accum_, transmittance_;
    gl::Framebuffer fbo_;
};

}  // namespace strata::approximate
