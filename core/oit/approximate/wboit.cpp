// Weighted blended OIT (McGuire and Bavoil, JCGT 2013): one geometry pass accumulates each
// fragment's premultiplied colour and alpha times a depth weight w(z, alpha) (additive), and
// the revealage prod(1 - alpha) (multiplicative); a full-screen pass composites the weighted
// average colour over the opaque colour. Order-independent and cheap, but approximate: the
// weight only favours nearer fragments, so the result is exact only for one layer or equal
// colours. Default weight: the paper's equation (7), on eye distance reconstructed from the
// reversed-Z window depth and the camera's near/far planes.
#include "oit/approximate/accumulation_targets.hpp"
#include "oit/approximate/approximate_entries.hpp"
#include "oit/draw_transparent.hpp"
#include "render/bindings.hpp"

namespace strata::approximate {
namespace {

class Wboit final : public Technique {
public:
    explicit Wboit(TechniqueInfo info) : info_(std::move(info)) {}
    const TechniqueInfo& info() const override { return info_; }

    std::vector<Parameter> parameters() override {
        return {{"weight", "the paper's depth weight: equation 7, 8, 9 (eye distance) or 10 (window depth)",
                 &weightEquation_, 7, 10, true}};
    }

    void render(const FrameContext& frame) override {
        if (!accumulateProgram_.program) {
            accumulateProgram_ = buildSceneProgram("oit/approximate/wboit_accumulate.frag.glsl");
            compositeProgram_ = gl::buildProgram({"common/fullscreen.vert.glsl", "oit/approximate/wboit_composite.frag.glsl"});
            samples_ = gl::createQuery(GL_SAMPLES_PASSED);
        }
        stats_ = {};
        GLuint program = accumulateProgram_.id();
        glProgramUniform1f(program, glGetUniformLocation(program, "uNear"), frame.camera.nearPlane);
        glProgramUniform1f(program, glGetUniformLocation(program, "uFar"), frame.camera.farPlane);
        glProgramUniform1i(program, glGetUniformLocation(program, "uWeightEquation"), int(weightEquation_));
        {
            gl::ScopedPass pass(frame.timer, "wboit accumulate");
            targets_.beginAccumulation(frame);
            // Every fragment in front of the opaque depth is blended: an occlusion query counts them.
            glBeginQuery(GL_SAMPLES_PASSED, samples_.id());
            stats_.objectDraws = drawTransparent(frame, accumulateProgram_, frame.transparentOrder);
            glEndQuery(GL_SAMPLES_PASSED);
            targets_.endAccumulation();
        }
        {
            gl::ScopedPass pass(frame.timer, "wboit composite");
            glBindFramebuffer(GL_FRAMEBUFFER, frame.targets.outputFramebuffer());
            glBindTextureUnit(bindings::kOpaqueColor, frame.targets.opaqueColor());
            drawFullscreen(frame, compositeProgram_.id());
        }
        stats_.passes = 2;
        stats_.bytes = std::uint64_t(frame.size.x) * frame.size.y * targets_.bytesPerPixel();
        GLuint64 blended = 0;
        glGetQueryObjectui64v(samples_.id(), GL_QUERY_RESULT, &blended);
        stats_.fragmentsCaptured = blended;
    }

private:
    TechniqueInfo info_;
    SceneProgram accumulateProgram_;
    gl::Program compositeProgram_;
    gl::Query samples_;
    // RGBA32F accumulation (the paper's RGBA16F overflows past ~20 layers at weight 3e3) and
    // R16F revealage (finer than the paper's R8 at small alpha).
    AccumulationTargets targets_{GL_R16F};
    double weightEquation_ = 7;
};

}  // namespace

TechniqueEntry wboitEntry() {
    TechniqueInfo info{"wboit", "approximate", false, false, "2", "w*h*18 (RGBA32F accumulation + R16F revealage)",
                       "weighted blended OIT (McGuire-Bavoil 2013): depth-weighted average colour, exact coverage"};
    return {info, [info] { return std::make_unique<Wboit>(info); }};
}

}  // namespace strata::approximate
