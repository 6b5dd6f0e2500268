#pragma once
// The geometry pass every technique shares: the transparent objects in a given order, depth
// tested against the opaque depth (reversed-Z: GL_GREATER passes nearer fragments) without
// depth writes, both faces, into whatever framebuffer is bound.
#include "oit/technique.hpp"
#include "render/scene_program.hpp"

#include <optional>
#include <vector>

namespace strata {

// Binds `program`, sets the frame uniforms and draws `order`; returns the number of draws.
std::uint64_t drawTransparent(const FrameContext& frame, const SceneProgram& program, const std::vector<int>& order);

// Depth test against the opaque depth, no writes, no culling, full viewport.
void setTransparentDepthState(const FrameContext& frame);

// Draws one full-screen triangle with `program` (depth test off).
void drawFullscreen(const FrameContext& frame, GLuint program);
// A full-screen draw that writes depth (GL_ALWAYS, depth writes on, left off after) into the
// bound framebuffer: a per-pixel depth bound a following geometry pass tests against.
void drawFullscreenDepth(const FrameContext& frame, GLuint program);
// A full-screen triangle under the depth and blend state the caller set (both above set theirs).
void drawFullscreenAsSet(const FrameContext& frame, GLuint program);

// The frame's transparent area (FrameContext::transparentArea) within `within` (a screen tile or
// band); `within` itself where the area is unset.
PixelRect transparentAreaWithin(const FrameContext& frame, const PixelRect& within);

// Scissors the draws in its scope to the frame's transparent area, within a tile or band when
// given, for the full-screen passes that change nothing where no transparent fragment lies: a
// layer's blend, a composite over the opaque colour the output already holds, a resolve. On a
// view where the glass covers a tenth of the screen they shade a tenth of the pixels. The
// scissor test is off after.
class TransparentAreaScissor {
public:
    explicit TransparentAreaScissor(const FrameContext& frame, std::optional<PixelRect> within = std::nullopt);
    ~TransparentAreaScissor();
    TransparentAreaScissor(const TransparentAreaScissor&) = delete;
    TransparentAreaScissor& operator=(const TransparentAreaScissor&) = delete;

private:
    bool on_ = false;
};

// Masks colour writes to the given draw buffers of the bound framebuffer in its scope, for a
// shader build that leaves those targets as they are (the coplanarity variants' NO_OPEN_LAYER
// resolves): what it writes there is not kept. Unmasked after.
class MaskedDrawBuffers {
public:
    explicit MaskedDrawBuffers(std::vector<GLuint> buffers);
    ~MaskedDrawBuffers();
    MaskedDrawBuffers(const MaskedDrawBuffers&) = delete;
    MaskedDrawBuffers& operator=(const MaskedDrawBuffers&) = delete;

private:
    std::vector<GLuint> buffers_;
};

// Sets the uniforms of shaders/oit/ordered_composite.glsl (the tie rule of
// render/depth_order.hpp) on a resolve program: the camera's n / (f - n) and the scene's
// relative tie tolerance.
void setDepthOrderUniforms(const FrameContext& frame, GLuint program);

// Transparent objects sorted back to front by the distance of their bounds' centres.
std::vector<int> sortedBackToFront(const FrameContext& frame);

}  // namespace strata
