// `dual`: dual depth peeling (Bavoil and Myers 2008), adapted to reversed-Z. An initialisation
// pass finds each pixel's nearest and farthest depth (MAX blending of (z, -z) into RG32F, with
// the hardware depth test only against the opaque depth); each peel pass then extracts the
// front and the back layer at once and finds the next range from the fragments strictly
// between them, and a full-screen pass blends the front layer under the front accumulation and
// the back layer over the back accumulation. ceil(D/2) peel passes: the peel pass counts the
// fragments strictly inside the range, and when there are none the next pass is not issued.
// Coincident fragments at the nearest (farthest) depth merge by MAX: not coplanarity-aware.
#include "oit/technique.hpp"

#include "common/bindings.h"
#include "oit/draw_transparent.hpp"
#include "oit/peeling/object_skipper.hpp"
#include "oit/peeling/peel_bindings.h"
#include "oit/peeling/peeling_settings.hpp"
#include "oit/precision.hpp"

namespace strata::peeling {
namespace {

class DualPeeling final : public TechniqueWithSettings<PeelingSettings> {
public:
    using TechniqueWithSettings::TechniqueWithSettings;

    void render(const FrameContext& frame) override {
        ensurePrograms();
        ensureTargets(frame.size);
        stats_ = {};
        skipper_.beginFrame(frame, settings_.skipPeeled);
        std::uint64_t total = initialise(frame);
        if (total > 0) {
            const float clearAccum[4] = {0, 0, 0, 1};
            glClearTexImage(frontAccum_.id(), 0, GL_RGBA, GL_FLOAT, clearAccum);
            glClearTexImage(backAccum_.id(), 0, GL_RGBA, GL_FLOAT, clearAccum);
            for (int pass = 1;; ++pass) {
                if (pass > settings_.maxPasses) {
                    stats_.overflowed = true;
                    break;
                }
                int cur = pass % 2;
                peel(frame, cur);
                if (!blend(frame, cur)) break;
                skipper_.query(frame, minMax_[cur].id(),
                               {RemainingSide::NotNearerThanR, RemainingSide::NotFartherThanG});
            }
            composite(frame);
        }
        skipper_.endFrame(stats_);
        stats_.fragmentsDropped = total - std::min(total, stats_.fragmentsCaptured);
        std::uint64_t pixels = std::uint64_t(frame.size.x) * frame.size.y;
        // Two RG32F min-max targets (8 B), front and back layers and front and back
        // accumulations (RGBA16F, 8 B, or RGBA32F, 16 B, each).
        stats_.bytes = pixels * (2 * 8 + 4 * floatTexelBytes(settings_.precision, 4));
    }

private:
    void ensurePrograms() {
        if (initProgram_.program) return;
        initProgram_ = buildSceneProgram("oit/peeling/dual_init.frag.glsl");
        samples_ = gl::createQuery(GL_SAMPLES_PASSED);
        peelProgram_ = buildSceneProgram("oit/peeling/dual_peel.frag.glsl");
        blendProgram_ = gl::buildProgram({"common/fullscreen.vert.glsl", "oit/peeling/dual_blend.frag.glsl"});
        compositeProgram_ = gl::buildProgram({"common/fullscreen.vert.glsl", "oit/peeling/peel_composite.frag.glsl"}, {{"DUAL", ""}});
        frontLayers_ = gl::createQuery(GL_SAMPLES_PASSED);
        backLayers_ = gl::createQuery(GL_SAMPLES_PASSED);
        interiorLeft_ = gl::createQuery(GL_ANY_SAMPLES_PASSED);
    }

    void ensureTargets(glm::ivec2 size) {
        if (size != size_ || settings_.precision != allocatedPrecision_) {
            size_ = size;
            allocatedPrecision_ = settings_.precision;
            // Depths stay 32-bit; colours (alpha + 1 in the layers: 1 to 2, steps of 2^-10 in
            // half float) follow the precision.
            const GLenum rgba = rgbaFloatFormat(settings_.precision);
            for (auto& t : minMax_) t = gl::createTexture2D(GL_RG32F, size.x, size.y);
            front_ = gl::createTexture2D(rgba, size.x, size.y);
            back_ = gl::createTexture2D(rgba, size.x, size.y);
            frontAccum_ = gl::createTexture2D(rgba, size.x, size.y);
            backAccum_ = gl::createTexture2D(rgba, size.x, size.y);
            blendFbo_ = gl::Framebuffer::create();
            glNamedFramebufferTexture(blendFbo_.id(), GL_COLOR_ATTACHMENT0, frontAccum_.id(), 0);
            glNamedFramebufferTexture(blendFbo_.id(), GL_COLOR_ATTACHMENT1, backAccum_.id(), 0);
            const GLenum two[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
            glNamedFramebufferDrawBuffers(blendFbo_.id(), 2, two);
        }
    }

    // The peel framebuffer is re-attached on every use: it shares the frame's opaque depth,
    // whose texture the frame targets replace when the size changes.
    void bindPeelTargets(const FrameContext& frame, int cur, bool withLayers) {
        if (!peelFbo_) peelFbo_ = gl::Framebuffer::create();
        GLuint fbo = peelFbo_.id();
        glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0, minMax_[cur].id(), 0);
        glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT1, withLayers ? front_.id() : 0, 0);
        glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT2, withLayers ? back_.id() : 0, 0);
        glNamedFramebufferTexture(fbo, GL_DEPTH_ATTACHMENT, frame.targets.depth(), 0);
        const GLenum three[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
        glNamedFramebufferDrawBuffers(fbo, withLayers ? 3 : 1, three);
        const float clearRange[4] = {-2, -2, 0, 0};
        glClearTexImage(minMax_[cur].id(), 0, GL_RGBA, GL_FLOAT, clearRange);
        if (withLayers) {
            glClearTexImage(front_.id(), 0, GL_RGBA, GL_FLOAT, nullptr);
            glClearTexImage(back_.id(), 0, GL_RGBA, GL_FLOAT, nullptr);
        }
        glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        setTransparentDepthState(frame);  // against the opaque depth, no writes
        glEnable(GL_BLEND);
        glBlendEquation(GL_MAX);
    }

    std::uint64_t initialise(const FrameContext& frame) {
        gl::ScopedPass pass(frame.timer, "dual init");
        bindPeelTargets(frame, 0, false);
        glBeginQuery(GL_SAMPLES_PASSED, samples_.id());
        skipper_.draw(frame, initProgram_, stats_);
        glEndQuery(GL_SAMPLES_PASSED);
        glBlendEquation(GL_FUNC_ADD);
        glDisable(GL_BLEND);
        ++stats_.passes;
        const std::uint64_t total = gl::queryResult(samples_);
        return total;
    }

    // Peels the front and back layers using minMax_[1 - cur]; the next range goes to
    // minMax_[cur].
    void peel(const FrameContext& frame, int cur) {
        gl::ScopedPass pass(frame.timer, "dual peel");
        bindPeelTargets(frame, cur, true);
        glBindTextureUnit(gpu::BIND_PEEL_PREVIOUS, minMax_[1 - cur].id());
        skipper_.draw(frame, peelProgram_, stats_);
        glBlendEquation(GL_FUNC_ADD);
        glDisable(GL_BLEND);
        ++stats_.passes;
    }

    // Blends the layers just peeled and adds them to fragmentsCaptured; returns whether any
    // pixel has fragments left strictly inside the next range (minMax_[cur]). Three full-screen
    // draws under occlusion queries (dual_blend.frag.glsl): counting with atomics instead cost
    // half of this pass on llvmpipe.
    bool blend(const FrameContext& frame, int cur) {
        gl::ScopedPass pass(frame.timer, "dual blend");
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
        glBindFramebuffer(GL_FRAMEBUFFER, blendFbo_.id());
        glViewport(0, 0, frame.size.x, frame.size.y);
        glEnable(GL_BLEND);
        glBlendEquation(GL_FUNC_ADD);
        glBlendFuncSeparatei(0, GL_DST_ALPHA, GL_ONE, GL_ZERO, GL_ONE_MINUS_SRC_ALPHA);           // under
        glBlendFuncSeparatei(1, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE_MINUS_SRC_ALPHA);  // over
        glBindTextureUnit(gpu::BIND_PEEL_LAYER, front_.id());
        glBindTextureUnit(gpu::BIND_PEEL_BACK, back_.id());
        glBindTextureUnit(gpu::BIND_PEEL_PREVIOUS, minMax_[cur].id());
        const GLuint program = blendProgram_.id();
        const GLint step = glGetUniformLocation(program, "uStep");
        auto drawStep = [&](int s, bool front, bool back, GLenum target, GLuint query) {
            glColorMaski(0, front, front, front, front);
            glColorMaski(1, back, back, back, back);
            glProgramUniform1i(program, step, s);
            glBeginQuery(target, query);
            drawFullscreen(frame, program);
            glEndQuery(target);
        };
        drawStep(0, true, false, GL_SAMPLES_PASSED, frontLayers_.id());
        drawStep(1, false, true, GL_SAMPLES_PASSED, backLayers_.id());
        drawStep(2, false, false, GL_ANY_SAMPLES_PASSED, interiorLeft_.id());
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glDisable(GL_BLEND);
        ++stats_.passes;
        GLuint64 front = 0, back = 0;
        GLuint left = 0;
        glGetQueryObjectui64v(frontLayers_.id(), GL_QUERY_RESULT, &front);
        glGetQueryObjectui64v(backLayers_.id(), GL_QUERY_RESULT, &back);
        glGetQueryObjectuiv(interiorLeft_.id(), GL_QUERY_RESULT, &left);
        stats_.fragmentsCaptured += front + back;
        // A pass that captured nothing had an empty range everywhere, so nothing is left
        // whatever the interior query says (a guard against a driver that skips the masked draw).
        return left != 0 && front + back > 0;
    }

    void composite(const FrameContext& frame) {
        gl::ScopedPass pass(frame.timer, "dual composite");
        glBindFramebuffer(GL_FRAMEBUFFER, frame.targets.outputFramebuffer());
        glDisable(GL_BLEND);
        glBindTextureUnit(gpu::BIND_OPAQUE_COLOR, frame.targets.opaqueColor());
        glBindTextureUnit(gpu::BIND_PEEL_ACCUM, frontAccum_.id());
        glBindTextureUnit(gpu::BIND_PEEL_BACK_ACCUM, backAccum_.id());
        drawFullscreen(frame, compositeProgram_.id());
        ++stats_.passes;
    }

    int allocatedPrecision_ = 0;
    SceneProgram initProgram_, peelProgram_;
    gl::Program blendProgram_, compositeProgram_;
    gl::Query samples_, frontLayers_, backLayers_, interiorLeft_;
    glm::ivec2 size_{0, 0};
    gl::Texture minMax_[2], front_, back_, frontAccum_, backAccum_;
    gl::Framebuffer peelFbo_, blendFbo_;
    ObjectSkipper skipper_;
};

}  // namespace
}  // namespace strata::peeling

namespace strata {

TechniqueEntry dualEntry() {
    TechniqueInfo info{"dual", "peeling", true, false, "2*ceil(D/2)+2 (init + ceil(D/2) peels + as many blends + composite)",
                       "w*h*48 B at precision=16: 2 RG32F min-max (8 each) + 2 layers + 2 accumulations RGBA16F "
                       "(8 each); w*h*80 B at 32 (RGBA32F, 16 each); Table 1: 6 words",
                       "dual depth peeling: nearest and farthest layer per pass, MAX-blended min-max depth"};
    return techniqueEntry<peeling::DualPeeling>(info);
}

}  // namespace strata
