// `f2b` and `f2b2`: front-to-back depth peeling (Everitt 2001), one layer per iteration.
//   f2b:  peel pass (geometry: nearest fragment strictly behind the previous layer, colour into
//         a layer target) + a full-screen pass blending that layer under the accumulation.
//   f2b2: depth-only pre-pass (geometry) + shading pass (geometry, GL_EQUAL with early-z)
//         blending straight under the accumulation.
// Both end with one full-screen composite over the opaque colour.
//
// Stopping: a counting pass before the first peel counts (samples passed) every transparent
// fragment in front of the opaque depth, and each layer pass counts the fragments it captured.
// The counts are read behind the passes (PeelLoop::runAhead): the next layer is issued before
// the last one's count is read while the counts read prove that more than a layer remains.
// When what is left equals what a layer captured nothing lies behind it and no further pass is
// issued, so D layers cost exactly D peels; a layer pass that captures nothing (only coincident
// leftovers were left, which a strict test never peels) stops it too. max_passes bounds the loop; hitting it is reported as an overflow.
//
// In a scene with coloured filters (oit/color_model.hpp) both composite them per channel: the
// accumulation (and f2b's layer target) gains a second target, what lets light through per
// channel, which f2b's layer pass and f2b2's shading pass read at their own pixel
// (f2b_layer_blend.frag.glsl, f2b2_shade.frag.glsl) between texture barriers.
#include "oit/technique.hpp"

#include "common/bindings.h"
#include "oit/color_model.hpp"
#include "oit/draw_transparent.hpp"
#include "oit/peeling/object_skipper.hpp"
#include "oit/peeling/peel_bindings.h"
#include "oit/peeling/peel_loop.hpp"
#include "oit/peeling/peeling_settings.hpp"
#include "oit/precision.hpp"

namespace strata::peeling {
namespace {

class FrontToBack final : public TechniqueWithSettings<PeelingSettings> {
public:
    FrontToBack(TechniqueInfo info, bool twoPass) : TechniqueWithSettings(std::move(info)), twoPass_(twoPass) {}

    void render(const FrameContext& frame) override {
        const ColorModel model = colorModelFor(frame.scene);
        ensurePrograms(model);
        ensureTargets(frame.size, model);
        PeelLoop loop(frame, stats_, skipper_, settings_.skipPeeled);
        clearAccumulation(accum_.id(), rgb() ? accumFilter_.id() : 0);
        PeelLoopOptions options;
        options.maxPasses = settings_.maxPasses;
        // What is left lies behind the layer just peeled.
        options.between = [&](int layer) { skipper_.query(frame, depth_[layer % 2].id(), {RemainingSide::NotNearerThanR}); };
        // What lies strictly behind a layer is what lay behind the previous one less the
        // fragments just captured (the loop's remaining count).
        loop.setTotal(countFragments(frame));
        // A layer takes at most one fragment a pixel: while the counts read so far prove that
        // more remains, the next layers go out before this one's count is read (read_ahead).
        if (settings_.readAhead) options.takenAtMost = std::uint64_t(frame.size.x) * std::uint64_t(frame.size.y);
        // Everything lies behind the opaque surfaces: nothing to peel.
        if (loop.remaining() > 0)
            loop.runAhead(
                options,
                [&](int layer) {
                    const int cur = layer % 2;
                    peel(frame, layer, cur);
                    if (twoPass_) shade(frame, cur, layerSamples(layer));
                    else blendLayer(frame, cur, layerSamples(layer));
                },
                [&](int layer) {
                    const std::uint64_t captured = gl::queryResult(layerSamples(layer));
                    return PeelStep{captured, captured};
                });
        if (stats_.fragmentsCaptured > 0) composite(frame);
        loop.finish();
        std::uint64_t pixels = std::uint64_t(frame.size.x) * frame.size.y;
        // Two depth buffers (4 B; f2b2: depth-stencil, 8 B), f2b's layer colour and the
        // accumulation (RGBA16F, 8 B, or RGBA32F, 16 B, each).
        const std::uint64_t rgba = floatTexelBytes(settings_.precision, 4);
        // With coloured filters, the accumulated filter (and f2b's layer filter) besides.
        stats_.bytes = pixels * (twoPass_ ? 2 * 8 + (rgb() ? 2 : 1) * rgba : 2 * 4 + (rgb() ? 4 : 2) * rgba);
    }

private:
    bool rgb() const { return model_ == ColorModel::RgbTransmittance; }

    void ensurePrograms(ColorModel model) {
        Programs& p = programs_.use(model);
        if (!p.peel.program) {
            gl::Defines defines = withColorModel({}, model);
            if (twoPass_) defines["DEPTH_ONLY"] = "";
            p.peel = buildSceneProgram("oit/peeling/f2b_peel.frag.glsl", defines);
            // The first layer has no previous depth to test against (f2b_peel.frag.glsl).
            defines["FIRST_LAYER"] = "";
            p.peelFirst = buildSceneProgram("oit/peeling/f2b_peel.frag.glsl", defines);
            if (twoPass_)
                p.shade = buildSceneProgram("oit/peeling/f2b2_shade.frag.glsl", withColorModel({}, model));
            else
                p.blend = buildFullscreenProgram("oit/peeling/f2b_layer_blend.frag.glsl", model);
            p.composite = buildFullscreenProgram("oit/peeling/peel_composite.frag.glsl", model);
        }
        if (samples_) return;
        countProgram_ = buildSceneProgram("oit/peeling/f2b_count.frag.glsl");
        samples_ = gl::createQuery(GL_SAMPLES_PASSED);
    }

    void ensureTargets(glm::ivec2 size, ColorModel model) {
        if (size == size_ && settings_.precision == allocatedPrecision_ && model == model_) return;
        size_ = size;
        allocatedPrecision_ = settings_.precision;
        model_ = model;
        const GLenum format = rgbaFloatFormat(settings_.precision);
        accum_ = gl::createTexture2D(format, size.x, size.y);
        const GLenum both[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
        layerFilter_ = {};
        accumFilter_ = {};
        if (rgb()) accumFilter_ = gl::createTexture2D(format, size.x, size.y);
        if (!twoPass_) {
            layerColor_ = gl::createTexture2D(format, size.x, size.y);
            accumFbo_ = gl::Framebuffer::create();
            glNamedFramebufferTexture(accumFbo_.id(), GL_COLOR_ATTACHMENT0, accum_.id(), 0);
            if (rgb()) {
                layerFilter_ = gl::createTexture2D(format, size.x, size.y);
                glNamedFramebufferTexture(accumFbo_.id(), GL_COLOR_ATTACHMENT1, accumFilter_.id(), 0);
                glNamedFramebufferDrawBuffers(accumFbo_.id(), 2, both);
            }
        }
        for (int i = 0; i < 2; ++i) {
            depth_[i] = gl::createTexture2D(twoPass_ ? GL_DEPTH32F_STENCIL8 : GL_DEPTH_COMPONENT32F, size.x, size.y);
            fbo_[i] = gl::Framebuffer::create();
            // f2b peels into the layer target; f2b2's passes write the accumulation directly.
            glNamedFramebufferTexture(fbo_[i].id(), GL_COLOR_ATTACHMENT0, twoPass_ ? accum_.id() : layerColor_.id(), 0);
            glNamedFramebufferTexture(fbo_[i].id(), twoPass_ ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT,
                                      depth_[i].id(), 0);
            if (rgb()) {
                // f2b: the layer's filter; f2b2: the accumulated one, which its shading pass blends.
                glNamedFramebufferTexture(fbo_[i].id(), GL_COLOR_ATTACHMENT1,
                                          twoPass_ ? accumFilter_.id() : layerFilter_.id(), 0);
                glNamedFramebufferDrawBuffers(fbo_[i].id(), 2, both);
            }
        }
    }

    // Every transparent fragment in front of the opaque depth (f2b_count.frag.glsl), drawn into
    // the output framebuffer, which holds that depth, with colour writes off.
    std::uint64_t countFragments(const FrameContext& frame) {
        gl::ScopedPass pass(frame.timer, twoPass_ ? "f2b2 count" : "f2b count");
        glBindFramebuffer(GL_FRAMEBUFFER, frame.targets.outputFramebuffer());
        setTransparentDepthState(frame);
        glDisable(GL_BLEND);
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glBeginQuery(GL_SAMPLES_PASSED, samples_.id());
        skipper_.draw(frame, countProgram_, stats_);
        glEndQuery(GL_SAMPLES_PASSED);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        ++stats_.passes;
        const std::uint64_t total = gl::queryResult(samples_);
        return total;
    }

    // The peel (f2b) or depth pre-pass (f2b2) of `layer` into depth_[cur].
    void peel(const FrameContext& frame, int layer, int cur) {
        gl::ScopedPass pass(frame.timer, twoPass_ ? "f2b2 depth" : "f2b peel");
        glBindFramebuffer(GL_FRAMEBUFFER, fbo_[cur].id());
        // Framebuffer clears obey the write masks, which the previous pass left off.
        glDepthMask(GL_TRUE);
        glStencilMask(0xFF);
        if (twoPass_)
            glClearNamedFramebufferfi(fbo_[cur].id(), GL_DEPTH_STENCIL, 0, 0.0f, 0);
        else {
            const float zeroDepth = 0.0f;
            glClearNamedFramebufferfv(fbo_[cur].id(), GL_DEPTH, 0, &zeroDepth);
        }
        setTransparentDepthState(frame);
        glDepthMask(GL_TRUE);
        glDisable(GL_BLEND);
        glDisable(GL_STENCIL_TEST);
        if (twoPass_) glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glBindTextureUnit(gpu::BIND_OPAQUE_DEPTH, frame.targets.depth());
        if (layer > 0) glBindTextureUnit(gpu::BIND_PEEL_PREVIOUS, depth_[1 - cur].id());
        skipper_.draw(frame, layer == 0 ? programs_->peelFirst : programs_->peel, stats_);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glDepthMask(GL_FALSE);
        ++stats_.passes;
        // No memory barrier: the next passes sample what this one rendered, which GL orders by
        // itself (barriers are for image and buffer stores; on llvmpipe one is a full finish).
    }

    // The "under" blend of f2b's layer pass and f2b2's shading pass. Per channel, the pass reads
    // the accumulated filter it writes: each pixel its own texel, once, which GL allows when a
    // texture barrier separates the draws (ARB_texture_barrier; the caller ends with another).
    void underBlending() const {
        glEnable(GL_BLEND);
        glBlendEquation(GL_FUNC_ADD);
        if (!rgb()) {
            glBlendFuncSeparate(GL_DST_ALPHA, GL_ONE, GL_ZERO, GL_ONE_MINUS_SRC_ALPHA);
            return;
        }
        glTextureBarrier();
        glBlendFunci(0, GL_ONE, GL_ONE);         // colour += T x layer colour
        glBlendFunci(1, GL_ZERO, GL_SRC_COLOR);  // T *= layer filter
        glBindTextureUnit(gpu::BIND_PEEL_ACCUM_FILTER, accumFilter_.id());
    }

    // The samples query of `layer`'s capture: one per layer, since several may be in flight.
    const gl::Query& layerSamples(int layer) {
        while (layerSamples_.size() <= std::size_t(layer)) layerSamples_.push_back(gl::createQuery(GL_SAMPLES_PASSED));
        return layerSamples_[std::size_t(layer)];
    }

    // Blends the layer just peeled under the accumulation, counting it into `samples`.
    void blendLayer(const FrameContext& frame, int cur, const gl::Query& samples) {
        gl::ScopedPass pass(frame.timer, "f2b blend");
        glBindFramebuffer(GL_FRAMEBUFFER, accumFbo_.id());
        glBindTextureUnit(gpu::BIND_PEEL_PREVIOUS, depth_[cur].id());
        glBindTextureUnit(gpu::BIND_PEEL_LAYER, layerColor_.id());
        if (rgb()) glBindTextureUnit(gpu::BIND_PEEL_LAYER_FILTER, layerFilter_.id());
        underBlending();
        glBeginQuery(GL_SAMPLES_PASSED, samples.id());
        {
            TransparentAreaScissor scissor(frame);  // no layer lies outside it
            drawFullscreen(frame, programs_->blend.id());
        }
        glEndQuery(GL_SAMPLES_PASSED);
        if (rgb()) glTextureBarrier();
        glDisable(GL_BLEND);
        ++stats_.passes;
    }

    // f2b2: shades the layer just found and blends it under the accumulation, counting it.
    void shade(const FrameContext& frame, int cur, const gl::Query& samples) {
        gl::ScopedPass pass(frame.timer, "f2b2 shade");
        glBindFramebuffer(GL_FRAMEBUFFER, fbo_[cur].id());
        setTransparentDepthState(frame);
        glDepthFunc(GL_EQUAL);
        glEnable(GL_STENCIL_TEST);
        glStencilFunc(GL_EQUAL, 0, 0xFF);
        glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
        underBlending();
        glBeginQuery(GL_SAMPLES_PASSED, samples.id());
        skipper_.draw(frame, programs_->shade, stats_);
        glEndQuery(GL_SAMPLES_PASSED);
        if (rgb()) glTextureBarrier();
        glDisable(GL_BLEND);
        glDisable(GL_STENCIL_TEST);
        ++stats_.passes;
    }

    void composite(const FrameContext& frame) {
        gl::ScopedPass pass(frame.timer, twoPass_ ? "f2b2 composite" : "f2b composite");
        glBindFramebuffer(GL_FRAMEBUFFER, frame.targets.outputFramebuffer());
        glDisable(GL_BLEND);
        glBindTextureUnit(gpu::BIND_OPAQUE_COLOR, frame.targets.opaqueColor());
        glBindTextureUnit(gpu::BIND_PEEL_ACCUM, accum_.id());
        if (rgb()) glBindTextureUnit(gpu::BIND_PEEL_ACCUM_FILTER, accumFilter_.id());
        TransparentAreaScissor scissor(frame);  // the output holds the opaque colour elsewhere
        drawFullscreen(frame, programs_->composite.id());
        ++stats_.passes;
    }

    struct Programs {
        SceneProgram peel, peelFirst, shade;  // peelFirst: the first layer's, with no previous depth
        gl::Program blend, composite;
    };
    bool twoPass_;
    int allocatedPrecision_ = 0;
    ColorModel model_ = ColorModel::Scalar;  // the targets'
    ProgramsPerColorModel<Programs> programs_;  // oit/color_model.hpp
    SceneProgram countProgram_;
    gl::Query samples_;                   // the count pass's
    std::vector<gl::Query> layerSamples_;  // each layer's capture, by layer
    glm::ivec2 size_{0, 0};
    gl::Texture accum_, layerColor_, depth_[2];
    gl::Texture layerFilter_, accumFilter_;  // the RGB build's (what passes, per channel)
    gl::Framebuffer accumFbo_, fbo_[2];
    ObjectSkipper skipper_;
};

}  // namespace
}  // namespace strata::peeling

namespace strata {

TechniqueEntry f2bEntry() {
    TechniqueInfo info{"f2b", "peeling", true, false, "2D+2 (count + D peels + D layer blends + composite)",
                       "w*h*24 B at precision=16: 2 depth (4) + layer and accumulation RGBA16F (8 each); "
                       "w*h*40 B at 32 (RGBA32F, 16 each); + two more RGBA targets in a scene with coloured filters; "
                       "Table 1: 3 words",
                       "front-to-back depth peeling, one layer per pass, strict depth test; skips peeled objects"};
    info.rgbTransmittance = true;
    return techniqueEntry<peeling::FrontToBack>(info, false);
}

TechniqueEntry f2b2Entry() {
    TechniqueInfo info{"f2b2", "peeling", true, false, "2D+2 (count + D depth pre-passes + D EQUAL shading passes + composite)",
                       "w*h*24 B at precision=16: 2 depth-stencil (8) + accumulation RGBA16F (8); w*h*32 B at 32 "
                       "(RGBA32F accumulation, 16); + one more RGBA target in a scene with coloured filters",
                       "front-to-back peeling with a depth-only pre-pass and early-z GL_EQUAL shading per layer"};
    info.rgbTransmittance = true;
    return techniqueEntry<peeling::FrontToBack>(info, true);
}

}  // namespace strata
