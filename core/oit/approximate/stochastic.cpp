// Stochastic transparency (Enderton, Sintorn, Shirley, Luebke 2010), with the paper's alpha
// correction. S samples per pixel are "virtual": llvmpipe offers at most 4 MSAA samples, so
// each sample is one layer of an r32ui array image holding depth bits, and the stochastic depth
// test is an image atomicMax (reversed-Z: nearer = larger). This keeps the estimator exact to
// the paper for any S up to 64:
//   pass 1 (stochastic depth): a fragment covers sample s with probability alpha (independent
//          Bernoulli per sample, seeded by a hash of pixel, primitive, object and s); each
//          sample keeps the nearest covering depth;
//   pass 2 (accumulate): vis_i = share of samples whose stochastic depth is not nearer than
//          fragment i, an unbiased estimate of prod_{j in front}(1 - alpha_j); adds
//          (alpha_i c_i vis_i, alpha_i vis_i) and multiplies T_total by (1 - alpha_i) exactly;
//   composite: C = accum.rgb * (1 - T_total) / accum.a, final = C + T_total * opaque.
// The noise falls as 1/sqrt(S); the coverage (1 - T_total) is exact at any S.
#include "common/bindings.h"
#include "oit/approximate/accumulation_targets.hpp"
#include "oit/approximate/approximate_bindings.h"
#include "oit/technique.hpp"
#include "oit/draw_transparent.hpp"
#include "oit/precision.hpp"

namespace strata::approximate {
namespace {

struct StochasticSettings {
    int samples = 8;
    int precision = 16;
    static const SettingsSchema<StochasticSettings>& schema() {
        static const SettingsSchema<StochasticSettings> s{
            integerSetting(&StochasticSettings::samples, "samples", 1, 64, SettingChange::Reallocate,
                           "S, stochastic samples per pixel (noise falls as 1/sqrt(S))"),
            precisionSetting(&StochasticSettings::precision, "accumulation and transmittance"),
        };
        return s;
    }
};

class Stochastic final : public TechniqueWithSettings<StochasticSettings> {
public:
    using TechniqueWithSettings::TechniqueWithSettings;

    void render(const FrameContext& frame) override {
        if (!depthProgram_.program) {
            depthProgram_ = buildSceneProgram("oit/approximate/stochastic_depth.frag.glsl");
            accumulateProgram_ = buildSceneProgram("oit/approximate/stochastic_accumulate.frag.glsl");
            compositeProgram_ = gl::buildProgram({"common/fullscreen.vert.glsl", "oit/approximate/accumulation_composite.frag.glsl"},
                                                {{"ALPHA_CORRECTED", ""}});
            query_ = gl::createQuery(GL_SAMPLES_PASSED);
        }
        const int samples = settings_.samples;
        if (frame.size != depthsSize_ || samples != depthsLayers_) {
            sampleDepths_ = gl::createTexture(GL_TEXTURE_2D_ARRAY);
            glTextureStorage3D(sampleDepths_.id(), 1, GL_R32UI, frame.size.x, frame.size.y, samples);
            depthsSize_ = frame.size;
            depthsLayers_ = samples;
        }
        for (GLuint p : {depthProgram_.id(), accumulateProgram_.id()})
            glProgramUniform1i(p, glGetUniformLocation(p, "uSamples"), samples);
        stats_ = {};
        {
            gl::ScopedPass pass(frame.timer, "stochastic depth");
            GLuint far = 0;  // reversed-Z far plane: every fragment is nearer
            glClearTexImage(sampleDepths_.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &far);
            glBindFramebuffer(GL_FRAMEBUFFER, frame.targets.outputFramebuffer());
            setTransparentDepthState(frame);
            glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
            glBindImageTexture(gpu::BIND_SAMPLE_DEPTHS, sampleDepths_.id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_R32UI);
            stats_.objectDraws += drawTransparent(frame, depthProgram_, frame.transparentOrder);
            glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
            // TEXTURE_UPDATE: the next frame clears these image-atomic results with glClearTexImage.
            glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
        }
        {
            gl::ScopedPass pass(frame.timer, "stochastic accumulate");
            targets_.beginAccumulation(frame, settings_.precision);
            glBindImageTexture(gpu::BIND_SAMPLE_DEPTHS, sampleDepths_.id(), 0, GL_TRUE, 0, GL_READ_ONLY, GL_R32UI);
            // Every fragment in front of the opaque depth adds its (possibly zero) share.
            glBeginQuery(GL_SAMPLES_PASSED, query_.id());
            stats_.objectDraws += drawTransparent(frame, accumulateProgram_, frame.transparentOrder);
            glEndQuery(GL_SAMPLES_PASSED);
            targets_.endAccumulation();
        }
        {
            gl::ScopedPass pass(frame.timer, "stochastic composite");
            glBindFramebuffer(GL_FRAMEBUFFER, frame.targets.outputFramebuffer());
            glBindTextureUnit(gpu::BIND_OPAQUE_COLOR, frame.targets.opaqueColor());
            TransparentAreaScissor scissor(frame);  // the output holds the opaque colour elsewhere
            drawFullscreen(frame, compositeProgram_.id());
        }
        stats_.passes = 3;
        stats_.bytes = std::uint64_t(frame.size.x) * frame.size.y * (std::uint64_t(samples) * 4 + AccumulationTargets::bytesPerPixel(settings_.precision));
        const std::uint64_t blended = gl::queryResult(query_);
        stats_.fragmentsCaptured = blended;
    }

private:
    SceneProgram depthProgram_, accumulateProgram_;
    gl::Program compositeProgram_;
    gl::Query query_;
    gl::Texture sampleDepths_;
    glm::ivec2 depthsSize_{0, 0};
    int depthsLayers_ = 0;
    AccumulationTargets targets_;
};

}  // namespace
}  // namespace strata::approximate

namespace strata {

TechniqueEntry stochasticEntry() {
    TechniqueInfo info{"stochastic", "approximate", false, false, "3", "w*h*(S*4 + 20)",
                       "stochastic transparency (Enderton 2010), S virtual samples, alpha-corrected"};
    return techniqueEntry<approximate::Stochastic>(info);
}

}  // namespace strata
