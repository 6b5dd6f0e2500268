// The floor: not a transparency technique but the bench's lower bound. Every transparent
// fragment in front of the opaque depth is shaded once with the surfaceColor() every technique
// uses and added (ONE, ONE) to the output: output = opaque + sum_i alpha_i * colour_i. No OIT
// technique rasterizes and shades fewer fragments in fewer passes, so its time is what others
// are measured against (ms_over_floor). Its image is deliberately not transparency.
#include "oit/approximate/approximate_entries.hpp"
#include "oit/draw_transparent.hpp"

namespace strata::approximate {
namespace {

class Floor final : public Technique {
public:
    explicit Floor(TechniqueInfo info) : info_(std::move(info)) {}
    const TechniqueInfo& info() const override { return info_; }

    void render(const FrameContext& frame) override {
        if (!program_.program) {
            program_ = buildSceneProgram("oit/approximate/floor.frag.glsl");
            samples_ = gl::createQuery(GL_SAMPLES_PASSED);
        }
        stats_ = {};
        {
            gl::ScopedPass pass(frame.timer, "floor");
            glBindFramebuffer(GL_FRAMEBUFFER, frame.targets.outputFramebuffer());
            setTransparentDepthState(frame);
            glEnable(GL_BLEND);
            glBlendEquation(GL_FUNC_ADD);
            // Colour adds; the output's alpha stays 1.
            glBlendFuncSeparate(GL_ONE, GL_ONE, GL_ZERO, GL_ONE);
            glBeginQuery(GL_SAMPLES_PASSED, samples_.id());
            stats_.objectDraws = drawTransparent(frame, program_, frame.transparentOrder);
            glEndQuery(GL_SAMPLES_PASSED);
            glDisable(GL_BLEND);
            // Read inside the timed pass, as blend-unsorted does: the wait for the result makes a
            // deferred rasterizer (llvmpipe) finish this pass's fragments before its end stamp.
            GLuint64 rasterized = 0;
            glGetQueryObjectui64v(samples_.id(), GL_QUERY_RESULT, &rasterized);
            stats_.fragmentsCaptured = rasterized;
        }
        stats_.passes = 1;
    }

private:
    TechniqueInfo info_;
    SceneProgram program_;
    gl::Query samples_;
};

}  // namespace

TechniqueEntry floorEntry() {
    TechniqueInfo info{"floor", "floor", false, false, "1", "none",
                       "lower bound, not OIT: every fragment shaded once and added (opaque + sum alpha*colour)"};
    return {info, [info] { return std::make_unique<Floor>(info); }};
}

}  // namespace strata::approximate
