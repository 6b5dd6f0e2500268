// `f2b-2p` and `f2b-3p`: coplanarity-aware front-to-back peeling (depth-fighting paper,
// section 3.1.1, Algorithm 1), under the project's tie rule (coplanar_layer.glsl): a layer is
// every fragment within the tie tolerance of the nearest one left, and its fragments are taken
// in (object id, primitive id) order, two per iteration: the id-min one goes under the
// accumulation, the id-max one over the layer's far part, which joins the accumulation when the
// layer is done. So every fragment is composited once, in the reference's order.
//
// Per iteration:
//   f2b-2p: counting pass (geometry: id min, id max, count, next layer's anchor; colour sum) +
//           resolve (full screen) of the pixels whose layer holds one fragment left, which
//           tallies those holding two or more; only if there are any, an extraction (geometry)
//           and a second resolve of just those. Where the count is one the colour sum is the
//           fragment, so a scene without coplanarity costs one geometry and one full-screen pass
//           a layer, and a layer of C coplanar fragments 2C passes (Table 1: 2C(Zall)).
//   f2b-3p: depth pass (geometry, GL_GREATER: the next anchor) + band (the far edge of the
//           layer's tie band as depth) + counting pass (id min, id max, count; colour sum) +
//           resolve of the pixels with one, and where any hold two or more a shading pass (the
//           ids found) and their resolve.
//           The counting and shading passes test GL_GEQUAL against the band in hardware, so
//           what lies behind the layer is rejected before they shade it. The band is a
//           full-screen pass of its own only in the first iteration; after that the resolve
//           writes it for the state it leaves (a full-screen pass less a layer: f2b-3p / f2b on
//           builtin:layers:8 and 16 at 256x256, 2.07-2.26 -> 1.97-2.08 on llvmpipe). As in
//           f2b-2p, a layer of one fragment gets its colour from the counting pass's sum, so
//           where nothing is coplanar there is no shading pass.
// Both start with an initialisation pass (the first anchors, and the total by GL_SAMPLES_PASSED)
// and end with peel_composite. The loop stops once every fragment is captured (the captured
// count comes from the first resolve's two atomic counters, one atomic per subgroup of a
// full-screen pass), when an iteration captures nothing, or at max_passes (an overflow).
//
// In a scene with coloured filters (oit/color_model.hpp) every colour target gains a second
// one (coplanar_layer.glsl): each fragment's opacity and each partial's transmittance per
// channel, written beside the first by the same passes.
#include "oit/technique.hpp"

#include "common/bindings.h"
#include "gl/pass_counters.hpp"
#include "oit/color_model.hpp"
#include "oit/draw_transparent.hpp"
#include "oit/peeling/coplanar_ids.hpp"
#include "oit/peeling/object_skipper.hpp"
#include "oit/peeling/peel_bindings.h"
#include "oit/peeling/peel_loop.hpp"
#include "oit/peeling/peeling_settings.hpp"
#include "oit/precision.hpp"

namespace strata::peeling {
namespace {

class CoplanarFrontToBack final : public TechniqueWithSettings<PeelingSettings> {
public:
    CoplanarFrontToBack(TechniqueInfo info, bool threePass)
        : TechniqueWithSettings(std::move(info)), threePass_(threePass) {}

    void render(const FrameContext& frame) override {
        const ColorModel model = colorModelFor(frame.scene);
        ensurePrograms(model);
        ensureTargets(frame.size, model);
        PeelLoop loop(frame, stats_, skipper_, settings_.skipPeeled);
        if (!ids_.bind(frame)) stats_.overflowed = true;
        attachOpaqueDepth(frame);
        const float noLayer[4] = {-1.0f, 0.0f, -kNoId, 0.0f};
        glClearTexImage(state_.id(), 0, GL_RGBA, GL_FLOAT, noLayer);
        clearAccumulation(accum_.id(), rgb() ? accumPasses_.id() : 0);
        clearAccumulation(layer_.id(), rgb() ? layerPasses_.id() : 0);
        for (GLuint p : {programs_->count.id(), programs_->extract.id(), programs_->next.id(), programs_->band.id(),
                         threePass_ ? programs_->resolve.id() : 0u, threePass_ ? programs_->resolveNoOpenLayer.id() : 0u,
                         threePass_ ? programs_->resolveCoplanar.id() : 0u})
            if (p) setDepthOrderUniforms(frame, p);
        layerOpen_ = false;  // cleared above: no far part is open until a second resolve runs

        loop.setTotal(initialise(frame));
        if (loop.total() > 0) {
            PeelLoopOptions options;
            options.maxPasses = settings_.maxPasses;
            // What is left lies behind the layer just resolved (the state's depth).
            options.between = [&](int) { skipper_.query(frame, state_.id(), {RemainingSide::NotNearerThanR}); };
            // Every fragment of a layer is captured, coplanar ones included: what an iteration
            // takes out of the range is what it keeps.
            loop.run(options, [&](int iteration) {
                if (threePass_) {
                    nextAnchors(frame);
                    // Later iterations' bands come from the resolve before them (BAND_OUT).
                    if (iteration == 0) band(frame);
                }
                count(frame);
                // A pixel with one fragment left captures it (its colour is the counting pass's
                // sum), one with two or more its id-min and id-max fragments.
                const Resolved r = resolveSingles(frame);
                if (r.coplanarPixels > 0) {
                    extract(frame);
                    resolveCoplanar(frame);
                    layerOpen_ = true;  // where three or more were left, the far part stays open
                }
                const std::uint64_t captured = r.singlePixels + 2 * r.coplanarPixels;
                return PeelStep{captured, captured};
            });
        }
        if (stats_.fragmentsCaptured > 0) composite(frame);
        loop.finish();
        const std::uint64_t pixels = std::uint64_t(frame.size.x) * frame.size.y;
        // State and count RGBA32F (16 B each), min and max colour, layer far part and
        // accumulation (RGBA16F, 8 B, or RGBA32F, 16 B, each), as many again with coloured
        // filters; f2b-3p's next-anchor and band depths (4 B each).
        stats_.bytes = pixels * (2 * 16 + (rgb() ? 8 : 4) * floatTexelBytes(settings_.precision, 4) +
                                 (threePass_ ? 8 : 0));
    }

private:
    bool rgb() const { return model_ == ColorModel::RgbTransmittance; }

    void ensurePrograms(ColorModel model) {
        Programs& p = programs_.use(model);
        if (p.init.program) return;
        auto fullscreen = [model](const char* fragment, gl::Defines defines = {}) {
            return buildFullscreenProgram(fragment, model, std::move(defines));
        };
        auto scene = [model](const char* fragment, gl::Defines defines = {}) {
            return buildSceneProgram(fragment, withColorModel(std::move(defines), model));
        };
        p.init = buildSceneProgram("oit/peeling/coplanar_init.frag.glsl");
        if (threePass_) {
            p.next = buildSceneProgram("oit/peeling/coplanar_next.frag.glsl");
            // The counting and shading passes test against the layer band's far edge (band()).
            p.band = gl::buildProgram({"common/fullscreen.vert.glsl", "oit/peeling/coplanar_band.frag.glsl"});
            p.count = scene("oit/peeling/coplanar_count.frag.glsl", {{"BAND_DEPTH", ""}, {"SUM_COLOR", ""}});
            p.extract = scene("oit/peeling/coplanar_extract.frag.glsl", {{"BAND_DEPTH", ""}});
            p.resolve = fullscreen("oit/peeling/coplanar_resolve.frag.glsl", {{"NEXT_FROM_DEPTH", ""}, {"BAND_OUT", ""}});
            p.resolveNoOpenLayer = fullscreen("oit/peeling/coplanar_resolve.frag.glsl",
                                              {{"NEXT_FROM_DEPTH", ""}, {"BAND_OUT", ""}, {"NO_OPEN_LAYER", ""}});
            p.resolveCoplanar = fullscreen("oit/peeling/coplanar_resolve.frag.glsl",
                                           {{"NEXT_FROM_DEPTH", ""}, {"BAND_OUT", ""}, {"COPLANAR_PIXELS", ""}});
        } else {
            p.count = scene("oit/peeling/coplanar_count.frag.glsl", {{"NEXT_ANCHOR", ""}, {"SUM_COLOR", ""}});
            p.extract = scene("oit/peeling/coplanar_extract.frag.glsl");
            p.resolve = fullscreen("oit/peeling/coplanar_resolve.frag.glsl");
            p.resolveNoOpenLayer = fullscreen("oit/peeling/coplanar_resolve.frag.glsl", {{"NO_OPEN_LAYER", ""}});
            p.resolveCoplanar = fullscreen("oit/peeling/coplanar_resolve.frag.glsl", {{"COPLANAR_PIXELS", ""}});
        }
        p.composite = fullscreen("oit/peeling/peel_composite.frag.glsl");
        if (!samples_) samples_ = gl::createQuery(GL_SAMPLES_PASSED);
    }

    void ensureTargets(glm::ivec2 size, ColorModel model) {
        if (size == size_ && settings_.precision == allocatedPrecision_ && model == model_) return;
        size_ = size;
        allocatedPrecision_ = settings_.precision;
        model_ = model;
        const GLenum rgba = rgbaFloatFormat(settings_.precision);
        state_ = gl::createTexture2D(GL_RGBA32F, size.x, size.y);
        count_ = gl::createTexture2D(GL_RGBA32F, size.x, size.y);
        minColor_ = gl::createTexture2D(rgba, size.x, size.y);
        maxColor_ = gl::createTexture2D(rgba, size.x, size.y);
        layer_ = gl::createTexture2D(rgba, size.x, size.y);
        accum_ = gl::createTexture2D(rgba, size.x, size.y);
        for (gl::Texture* t : {&minOpacity_, &maxOpacity_, &layerPasses_, &accumPasses_}) *t = {};
        if (rgb()) {
            minOpacity_ = gl::createTexture2D(rgba, size.x, size.y);
            maxOpacity_ = gl::createTexture2D(rgba, size.x, size.y);
            layerPasses_ = gl::createTexture2D(rgba, size.x, size.y);
            accumPasses_ = gl::createTexture2D(rgba, size.x, size.y);
        }
        // The RGB build's second texels follow the first ones' attachments, in the shaders'
        // output locations.
        auto withRgb = [this](std::vector<GLuint> colors, std::initializer_list<GLuint> rgbColors) {
            if (rgb()) colors.insert(colors.end(), rgbColors);
            return gl::createFramebuffer(colors);
        };
        initFbo_ = gl::createFramebuffer({state_.id()});
        countFbo_ = withRgb({count_.id(), minColor_.id()}, {minOpacity_.id()});
        extractFbo_ = withRgb({minColor_.id(), maxColor_.id()}, {minOpacity_.id(), maxOpacity_.id()});
        resolveFbo_ = withRgb({accum_.id(), layer_.id(), state_.id()}, {accumPasses_.id(), layerPasses_.id()});
        if (threePass_) {
            nextDepth_ = gl::createTexture2D(GL_DEPTH_COMPONENT32F, size.x, size.y);
            nextFbo_ = gl::Framebuffer::create();
            glNamedFramebufferTexture(nextFbo_.id(), GL_DEPTH_ATTACHMENT, nextDepth_.id(), 0);
            glNamedFramebufferDrawBuffer(nextFbo_.id(), GL_NONE);
            // The band's far edge: the depth the counting and shading passes test against.
            bandDepth_ = gl::createTexture2D(GL_DEPTH_COMPONENT32F, size.x, size.y);
            bandFbo_ = gl::Framebuffer::create();
            glNamedFramebufferTexture(bandFbo_.id(), GL_DEPTH_ATTACHMENT, bandDepth_.id(), 0);
            glNamedFramebufferDrawBuffer(bandFbo_.id(), GL_NONE);
            for (const gl::Framebuffer* fbo : {&countFbo_, &extractFbo_, &resolveFbo_})
                glNamedFramebufferTexture(fbo->id(), GL_DEPTH_ATTACHMENT, bandDepth_.id(), 0);
        }
    }

    // The geometry passes test against the opaque depth in hardware (early, no writes); the
    // frame targets replace that texture when the size changes, so it is attached per frame.
    // f2b-3p's counting and shading passes test against the band's far edge instead (band()).
    void attachOpaqueDepth(const FrameContext& frame) {
        for (const gl::Framebuffer* fbo : {&initFbo_, &countFbo_, &extractFbo_})
            if (!threePass_ || fbo == &initFbo_)
                glNamedFramebufferTexture(fbo->id(), GL_DEPTH_ATTACHMENT, frame.targets.depth(), 0);
    }

    void bindTextures(const FrameContext& frame) {
        glBindTextureUnit(gpu::BIND_OPAQUE_DEPTH, frame.targets.depth());
        glBindTextureUnit(gpu::BIND_COPLANAR_STATE, state_.id());
        glBindTextureUnit(gpu::BIND_COPLANAR_COUNT, count_.id());
        glBindTextureUnit(gpu::BIND_COPLANAR_MIN_COLOR, minColor_.id());
        glBindTextureUnit(gpu::BIND_COPLANAR_MAX_COLOR, maxColor_.id());
        glBindTextureUnit(gpu::BIND_COPLANAR_LAYER, layer_.id());
        glBindTextureUnit(gpu::BIND_COPLANAR_ACCUM, accum_.id());
        if (threePass_) glBindTextureUnit(gpu::BIND_COPLANAR_NEXT_DEPTH, nextDepth_.id());
        if (!rgb()) return;
        glBindTextureUnit(gpu::BIND_COPLANAR_MIN_OPACITY, minOpacity_.id());
        glBindTextureUnit(gpu::BIND_COPLANAR_MAX_OPACITY, maxOpacity_.id());
        glBindTextureUnit(gpu::BIND_COPLANAR_LAYER_PASSES, layerPasses_.id());
        glBindTextureUnit(gpu::BIND_COPLANAR_ACCUM_PASSES, accumPasses_.id());
    }

    // Zeroes the id-min fragment's texels, the counting pass's colour sum: "none" for ADD.
    void clearColorSum() {
        for (const gl::Texture* t : {&minColor_, &minOpacity_})
            if (*t) glClearTexImage(t->id(), 0, GL_RGBA, GL_FLOAT, nullptr);
    }

    // MAX of the depth into the state's r (the other channels masked): the first anchors.
    std::uint64_t initialise(const FrameContext& frame) {
        gl::ScopedPass pass(frame.timer, "coplanar init");
        glBindFramebuffer(GL_FRAMEBUFFER, initFbo_.id());
        setTransparentDepthState(frame);
        glEnable(GL_BLEND);
        glBlendEquation(GL_MAX);
        glColorMask(GL_TRUE, GL_FALSE, GL_FALSE, GL_FALSE);
        glBeginQuery(GL_SAMPLES_PASSED, samples_.id());
        skipper_.draw(frame, programs_->init, stats_);
        glEndQuery(GL_SAMPLES_PASSED);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glBlendEquation(GL_FUNC_ADD);
        glDisable(GL_BLEND);
        ++stats_.passes;
        return gl::queryResult(samples_);
    }

    // f2b-3p: the nearest fragment beyond each pixel's layer into nextDepth_.
    void nextAnchors(const FrameContext& frame) {
        gl::ScopedPass pass(frame.timer, "f2b-3p depth");
        glBindFramebuffer(GL_FRAMEBUFFER, nextFbo_.id());
        glDepthMask(GL_TRUE);
        const float zero = 0.0f;
        glClearNamedFramebufferfv(nextFbo_.id(), GL_DEPTH, 0, &zero);
        setTransparentDepthState(frame);
        glDepthMask(GL_TRUE);
        bindTextures(frame);
        glBindTextureUnit(gpu::BIND_COPLANAR_NEXT_DEPTH, 0);  // the attachment is not also sampled
        skipper_.draw(frame, programs_->next, stats_);
        glDepthMask(GL_FALSE);
        ++stats_.passes;
    }

    // f2b-3p: the far edge of the tie band of each pixel's layer (the state's anchor) into
    // bandDepth_, so that the counting and shading passes reject before shading what lies behind
    // the layer: without it every fragment left behind it was shaded twice an iteration.
    void band(const FrameContext& frame) {
        gl::ScopedPass pass(frame.timer, "f2b-3p band");
        glBindFramebuffer(GL_FRAMEBUFFER, bandFbo_.id());
        bindTextures(frame);
        drawFullscreenDepth(frame, programs_->band.id());
        ++stats_.passes;
    }

    // The depth test of the counting and shading passes: f2b-3p's at or nearer than the band's
    // far edge; f2b-2p's nearer than the opaque depth.
    void layerDepthTest(const FrameContext& frame) {
        setTransparentDepthState(frame);
        if (threePass_) glDepthFunc(GL_GEQUAL);
    }

    void count(const FrameContext& frame) {
        gl::ScopedPass pass(frame.timer, threePass_ ? "f2b-3p count" : "f2b-2p count");
        const float countClear[4] = {kNoId, kNoId, kNoId, 0.0f};
        glClearTexImage(count_.id(), 0, GL_RGBA, GL_FLOAT, countClear);
        clearColorSum();
        glBindFramebuffer(GL_FRAMEBUFFER, countFbo_.id());
        layerDepthTest(frame);
        bindTextures(frame);
        glEnable(GL_BLEND);
        glBlendFunc(GL_ONE, GL_ONE);
        glBlendEquationSeparatei(0, GL_MAX, GL_FUNC_ADD);  // ids and anchor: MAX; count: ADD
        glBlendEquationi(1, GL_FUNC_ADD);                  // colour sum
        glBlendEquationi(2, GL_FUNC_ADD);                  // and opacity sum (rgb)
        skipper_.draw(frame, programs_->count, stats_);
        glBlendEquation(GL_FUNC_ADD);
        glBlendFunc(GL_ONE, GL_ZERO);
        glDisable(GL_BLEND);
        ++stats_.passes;
    }

    // The id-min and id-max fragments' colours by MAX blending into zeroed targets, for the
    // pixels the first resolve left (two or more in the layer). The min target's sums are spent
    // by then: that resolve read them where the layer held one.
    void extract(const FrameContext& frame) {
        gl::ScopedPass pass(frame.timer, threePass_ ? "f2b-3p shade" : "f2b-2p extract");
        for (const gl::Texture* t : {&minColor_, &maxColor_, &minOpacity_, &maxOpacity_})
            if (*t) glClearTexImage(t->id(), 0, GL_RGBA, GL_FLOAT, nullptr);
        glBindFramebuffer(GL_FRAMEBUFFER, extractFbo_.id());
        layerDepthTest(frame);
        bindTextures(frame);
        glEnable(GL_BLEND);
        glBlendEquation(GL_MAX);
        skipper_.draw(frame, programs_->extract, stats_);
        glBlendEquation(GL_FUNC_ADD);
        glDisable(GL_BLEND);
        ++stats_.passes;
    }

    struct Resolved {
        std::uint64_t coplanarPixels = 0;  // left for the extraction: two or more in the layer
        std::uint64_t singlePixels = 0;    // resolved: one fragment in the layer
    };

    // The pixels whose layer holds one fragment; tallies them and those holding more.
    Resolved resolveSingles(const FrameContext& frame) {
        gl::ScopedPass pass(frame.timer, threePass_ ? "f2b-3p resolve" : "f2b-2p resolve");
        resolveCounters_.reset();
        resolveCounters_.bind(gpu::BIND_COUNTERS);
        if (layerOpen_) {
            drawResolve(frame, programs_->resolve.id());
        } else {
            // The far part's targets (draw buffers 1, and 4 with coloured filters) keep their
            // clear, the empty partial.
            MaskedDrawBuffers farPart(rgb() ? std::vector<GLuint>{1, 4} : std::vector<GLuint>{1});
            drawResolve(frame, programs_->resolveNoOpenLayer.id());
        }
        resolveCounters_.fence();
        const auto counts = resolveCounters_.read();
        return Resolved{counts[0], counts[1]};
    }

    // The pixels the first resolve left, after their extraction.
    void resolveCoplanar(const FrameContext& frame) {
        gl::ScopedPass pass(frame.timer, threePass_ ? "f2b-3p resolve coplanar" : "f2b-2p resolve coplanar");
        drawResolve(frame, programs_->resolveCoplanar.id());
    }

    void drawResolve(const FrameContext& frame, GLuint program) {
        glBindFramebuffer(GL_FRAMEBUFFER, resolveFbo_.id());
        glViewport(0, 0, frame.size.x, frame.size.y);
        glDisable(GL_BLEND);
        bindTextures(frame);
        glTextureBarrier();  // it reads its own texel of three (rgb: five) of its attachments
        TransparentAreaScissor scissor(frame);  // nothing was counted outside it: a no-op there
        // f2b-3p: the next iteration's band depth too (BAND_OUT), in place of a band pass.
        if (threePass_) drawFullscreenDepth(frame, program);
        else drawFullscreen(frame, program);
        ++stats_.passes;
    }

    void composite(const FrameContext& frame) {
        gl::ScopedPass pass(frame.timer, threePass_ ? "f2b-3p composite" : "f2b-2p composite");
        glBindFramebuffer(GL_FRAMEBUFFER, frame.targets.outputFramebuffer());
        glDisable(GL_BLEND);
        glBindTextureUnit(gpu::BIND_OPAQUE_COLOR, frame.targets.opaqueColor());
        glBindTextureUnit(gpu::BIND_PEEL_ACCUM, accum_.id());
        if (rgb()) glBindTextureUnit(gpu::BIND_PEEL_ACCUM_FILTER, accumPasses_.id());
        TransparentAreaScissor scissor(frame);  // the output holds the opaque colour elsewhere
        drawFullscreen(frame, programs_->composite.id());
        ++stats_.passes;
    }

    struct Programs {
        SceneProgram init, next, count, extract;
        // resolveNoOpenLayer: the first resolve while no far part is open (NO_OPEN_LAYER)
        gl::Program resolve, resolveNoOpenLayer, resolveCoplanar, composite, band;
    };
    bool threePass_;
    bool layerOpen_ = false;  // this frame: a second resolve ran, so a far part may be open
    int allocatedPrecision_ = 0;
    ColorModel model_ = ColorModel::Scalar;  // the targets'
    ProgramsPerColorModel<Programs> programs_;  // oit/color_model.hpp
    gl::Query samples_;
    gl::PassCounters resolveCounters_;  // pixels with two or more left, pixels with one
    glm::ivec2 size_{0, 0};
    gl::Texture state_, count_, minColor_, maxColor_, layer_, accum_, nextDepth_, bandDepth_;
    gl::Texture minOpacity_, maxOpacity_, layerPasses_, accumPasses_;  // the RGB build's second texels
    gl::Framebuffer initFbo_, countFbo_, extractFbo_, resolveFbo_, nextFbo_, bandFbo_;
    CoplanarIds ids_;
    ObjectSkipper skipper_;
};

}  // namespace
}  // namespace strata::peeling

namespace strata {

TechniqueEntry f2b2pEntry() {
    TechniqueInfo info{"f2b-2p", "coplanarity", true, true,
                       "1 + sum over layers of 2C (count and resolve per iteration; an extraction and a second resolve "
                       "in those with C >= 2 left) + 1; no coplanarity: 2D+2 (init + D x (count, resolve) + composite); "
                       "Table 1: 2C(Zall)",
                       "w*h*64 B at precision=16: state and count RGBA32F (16 each) + min, max, layer and "
                       "accumulation RGBA16F (8 each); w*h*96 B at 32; + four more RGBA targets in a scene with "
                       "coloured filters; Table 1: 12 words (10 modern)",
                       "coplanarity-aware f2b (Algorithm 1): per layer id-min/id-max/count by MAX/ADD blending, "
                       "two coplanar fragments extracted per iteration in tie order"};
    info.rgbTransmittance = true;
    return techniqueEntry<peeling::CoplanarFrontToBack>(info, false);
}

TechniqueEntry f2b3pEntry() {
    TechniqueInfo info{"f2b-3p", "coplanarity", true, true,
                       "3 + sum over layers of (3*ceil(C/2) + 2*floor(C/2)) (depth, tie-test count and resolve per "
                       "iteration, and shading and a second resolve where two or more are left; the first also a "
                       "band pass, later ones get it from the resolve); no coplanarity: 3D+3; Table 1: 3C(Zall)/2",
                       "w*h*72 B at precision=16: as f2b-2p + next-anchor and band depths (4 each); w*h*104 B "
                       "at 32; + four more RGBA targets in a scene with coloured filters",
                       "coplanarity-aware f2b with a depth pass, a tie-test counting pass and a shading pass "
                       "per iteration (the shading only where a layer holds two or more)"};
    info.rgbTransmittance = true;
    return techniqueEntry<peeling::CoplanarFrontToBack>(info, true);
}

}  // namespace strata
