// The floor: not a transparency technique but the bench's lower bound. Every transparent
// fragment in front of the opaque depth is rasterized once and shaded once with the
// surfaceColor() every technique pays for, and written without blending into an R8 scratch
// target that shares the opaque depth: no atomics, no float blending, one byte per pixel
// written. A GL_SAMPLES_PASSED query counts the fragments. No OIT technique rasterizes and shades
// fewer fragments in fewer passes, so its time is what the others are measured against
// (ms_over_floor).
//
// Measured on llvmpipe (256x256, 16 full-screen layers, ms per frame, min..median of 3 runs): the
// target barely matters once the shader runs (R8 2.7-3.4, RGBA8 3.0-3.2, RGBA16F 3.3-3.9,
// RGBA32F with ONE/ONE blending 3.5; R8 against RGBA8 in 6 alternating runs: 7% less).
// Colour writes masked are cheaper (0.75) only because the driver then drops the shading as
// dead code: that measures rasterization alone, below what any technique that composites a
// colour can reach, so the floor keeps the shading.
//
// Its image is the opaque image (the output is left as the frame renderer copied it): the
// floor composites nothing, and its error columns are those of ignoring transparency.
#include "oit/technique.hpp"
#include "oit/draw_transparent.hpp"
#include "oit/scratch_target.hpp"

namespace strata::approximate {
namespace {

class Floor final : public TechniqueWithSettings<NoSettings> {
public:
    using TechniqueWithSettings::TechniqueWithSettings;

    void render(const FrameContext& frame) override {
        if (!program_.program) {
            program_ = buildSceneProgram("oit/approximate/floor.frag.glsl");
            samples_ = gl::createQuery(GL_SAMPLES_PASSED);
        }
        const GLuint fbo = scratch_.bind(frame.targets, frame.size, GL_R8, "floor");
        stats_ = {};
        {
            gl::ScopedPass pass(frame.timer, "floor");
            glBindFramebuffer(GL_FRAMEBUFFER, fbo);
            setTransparentDepthState(frame);
            glDisable(GL_BLEND);
            glBeginQuery(GL_SAMPLES_PASSED, samples_.id());
            stats_.objectDraws = drawTransparent(frame, program_, frame.transparentOrder);
            glEndQuery(GL_SAMPLES_PASSED);
            // Read inside the timed pass, as blend-unsorted does: the wait for the result makes a
            // deferred rasterizer (llvmpipe) finish this pass's fragments before its end stamp.
            const std::uint64_t rasterized = gl::queryResult(samples_);
            stats_.fragmentsCaptured = rasterized;
        }
        stats_.passes = 1;
        stats_.bytes = std::uint64_t(frame.size.x) * frame.size.y;
    }

private:
    SceneProgram program_;
    gl::Query samples_;
    ScratchTarget scratch_;
};

}  // namespace
}  // namespace strata::approximate

namespace strata {

TechniqueEntry floorEntry() {
    TechniqueInfo info{"floor", "floor", false, false, "1", "w*h*1 (R8 scratch colour, never read)",
                       "lower bound, not OIT: every fragment rasterized and shaded once into an R8 scratch "
                       "target, no blending; its image is the opaque image"};
    return techniqueEntry<approximate::Floor>(info);
}

}  // namespace strata
