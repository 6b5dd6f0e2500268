// Weighted blended OIT (McGuire and Bavoil, JCGT 2013): one geometry pass accumulates each
// fragment's premultiplied colour and alpha times a depth weight w(z, alpha) (additive), and
// the revealage prod(1 - alpha) (multiplicative); a full-screen pass composites the weighted
// average colour over the opaque colour. Order-independent and cheap, but approximate: the
// weight only favours nearer fragments, so the result is exact only for one layer or equal
// colours. Default weight: the paper's equation (7), on eye distance reconstructed from the
// reversed-Z window depth and the camera's near/far planes.
//
// Precision. A fragment adds up to alpha^2 * 3e3 (the weight clamp) to the accumulation's
// alpha, and half float ends at 65504: 22 opaque-ish fragments at the clamp (eye distance below
// ~0.3 scene units with equation 7) overflow RGBA16F (to infinity on GPUs; llvmpipe saturates,
// which skews the colour). The claim holds (precision_gl_test: 64 such fragments, 24% off). At
// precision=16 the weights are therefore scaled by 2^-4 (and the composite's clamp with them),
// which cancels in the weighted average: ~350 such fragments fit, and the smallest weight
// (alpha^2 * 1e-2 / 16) stays a normal half float down to alpha ~0.3 (a subnormal with steps of
// 1.5e-3 of it at 0.25).
#include "common/bindings.h"
#include "oit/approximate/accumulation_targets.hpp"
#include "oit/technique.hpp"
#include "oit/draw_transparent.hpp"
#include "oit/precision.hpp"

#include <map>
#include <string>

namespace strata::approximate {
namespace {

constexpr float kHalfWeightScale = 1.0f / 16.0f;  // a power of two: the scaling itself is exact

struct WboitSettings {
    int weight = 7;
    int precision = 16;
    static const SettingsSchema<WboitSettings>& schema() {
        static const SettingsSchema<WboitSettings> s{
            integerSetting(&WboitSettings::weight, "weight", 7, 10, SettingChange::Nothing,
                           "the paper's depth weight: equation 7, 8, 9 (eye distance) or 10 (window depth)"),
            precisionSetting(&WboitSettings::precision, "accumulation and revealage"),
        };
        return s;
    }
};

class Wboit final : public TechniqueWithSettings<WboitSettings> {
public:
    using TechniqueWithSettings::TechniqueWithSettings;

    void render(const FrameContext& frame) override {
        if (!compositeProgram_) {
            compositeProgram_ = gl::buildProgram({"common/fullscreen.vert.glsl", "oit/approximate/accumulation_composite.frag.glsl"},
                                                {{"WEIGHTED_AVERAGE", ""}});
            samples_ = gl::createQuery(GL_SAMPLES_PASSED);
        }
        SceneProgram& accumulate = accumulatePrograms_[settings_.weight];
        if (!accumulate.program)
            accumulate = buildSceneProgram("oit/approximate/wboit_accumulate.frag.glsl",
                                           {{"WEIGHT_EQUATION", std::to_string(settings_.weight)}});
        stats_ = {};
        GLuint program = accumulate.id();
        glProgramUniform1f(program, glGetUniformLocation(program, "uNear"), frame.camera.nearPlane);
        glProgramUniform1f(program, glGetUniformLocation(program, "uFar"), frame.camera.farPlane);
        const float weightScale = isHalf(settings_.precision) ? kHalfWeightScale : 1.0f;
        glProgramUniform1f(program, glGetUniformLocation(program, "uWeightScale"), weightScale);
        GLuint composite = compositeProgram_.id();
        glProgramUniform1f(composite, glGetUniformLocation(composite, "uWeightScale"), weightScale);
        {
            gl::ScopedPass pass(frame.timer, "wboit accumulate");
            targets_.beginAccumulation(frame, settings_.precision);
            // Every fragment in front of the opaque depth is blended: an occlusion query counts them.
            glBeginQuery(GL_SAMPLES_PASSED, samples_.id());
            stats_.objectDraws = drawTransparent(frame, accumulate, frame.transparentOrder);
            glEndQuery(GL_SAMPLES_PASSED);
            targets_.endAccumulation();
        }
        {
            gl::ScopedPass pass(frame.timer, "wboit composite");
            glBindFramebuffer(GL_FRAMEBUFFER, frame.targets.outputFramebuffer());
            glBindTextureUnit(gpu::BIND_OPAQUE_COLOR, frame.targets.opaqueColor());
            TransparentAreaScissor scissor(frame);  // the output holds the opaque colour elsewhere
            drawFullscreen(frame, compositeProgram_.id());
        }
        stats_.passes = 2;
        stats_.bytes = std::uint64_t(frame.size.x) * frame.size.y * AccumulationTargets::bytesPerPixel(settings_.precision);
        const std::uint64_t blended = gl::queryResult(samples_);
        stats_.fragmentsCaptured = blended;
    }

private:
    std::map<int, SceneProgram> accumulatePrograms_;  // per weight equation
    gl::Program compositeProgram_;
    gl::Query samples_;
    AccumulationTargets targets_;
};

}  // namespace
}  // namespace strata::approximate

namespace strata {

TechniqueEntry wboitEntry() {
    TechniqueInfo info{"wboit", "approximate", false, false, "2", "w*h*10 at precision=16 (RGBA16F accumulation + R16F revealage); w*h*20 at 32 (RGBA32F + R32F)",
                       "weighted blended OIT (McGuire-Bavoil 2013): depth-weighted average colour, exact coverage"};
    return techniqueEntry<approximate::Wboit>(info);
}

}  // namespace strata
