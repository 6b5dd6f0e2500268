// `dual-ll`, `dual-fab`: dual depth peeling that captures every coincident fragment of the front
// and the back layer (depth-fighting paper, sections 3.1.3 DUAL-LL and 3.2.1 DUAL-B). As `dual`:
// an initialisation pass finds each pixel's nearest and farthest depth (dual_init.frag.glsl);
// then each iteration's peel pass (dual_layer_peel.frag.glsl) stores the fragments within the
// tie tolerance of the nearest depth (front layer) and of the farthest (back layer) in per-pixel
// storage (layer_storage.hpp: dual-ll's lists, front nodes from the pool's start and back nodes
// from its end; dual-fab's K entries per pixel and side) and MAX-blends the next range from
// the rest; a full-screen resolve composites each layer in object order, the front under the
// front accumulation and the back over the back accumulation. The loop ends on the iteration
// whose layers hold the last of the fragments counted by the initialisation.
//
// In a scene with coloured filters (oit/color_model.hpp) the storage keeps a glass fragment's
// coloured filter (oit/packed_color.glsl) and each accumulation gains a second target, what it
// lets through per channel, which the resolve reads and writes at its own texel.
#include "oit/technique.hpp"

#include "common/bindings.h"
#include "oit/color_model.hpp"
#include "oit/draw_transparent.hpp"
#include "oit/peeling/layer_settings.hpp"
#include "oit/peeling/layer_storage.hpp"
#include "oit/peeling/object_skipper.hpp"
#include "oit/peeling/peel_bindings.h"
#include "oit/peeling/peel_loop.hpp"
#include "oit/precision.hpp"

#include <vector>

namespace strata::peeling {
namespace {

class DualLayers {
public:
    DualLayers(const std::string& id, LayerStore kind) : id_(id), storage_(kind, id) {}

    void render(const FrameContext& frame, const LayerPeelingSettings& s, TechniqueStats& stats) {
        const ColorModel model = colorModelFor(frame.scene);
        ensurePrograms(model);
        ensureTargets(frame.size, s.precision, model);
        PeelLoop loop(frame, stats, skipper_, s.skipPeeled);
        storage_.prepare(frame.size, 2, s.capacity, s.maxBlockMiB);
        setDepthOrderUniforms(frame, programs_->peel.id());
        loop.setTotal(initialise(frame, stats));
        if (loop.total() > 0) {
            clearAccumulation(frontAccum_.id(), rgb() ? frontPasses_.id() : 0);
            clearAccumulation(backAccum_.id(), rgb() ? backPasses_.id() : 0);
            PeelLoopOptions options;
            options.maxPasses = s.maxPasses;
            // What is left lies inside the next range, between its nearest and farthest depth.
            options.between = [&](int iteration) {
                skipper_.query(frame, minMax_[(iteration + 1) % 2].id(),
                               {RemainingSide::NotNearerThanR, RemainingSide::NotFartherThanG});
            };
            // Iteration i peels from minMax_[i % 2] into minMax_[(i + 1) % 2] (the init wrote minMax_[0]).
            loop.run(options, [&](int iteration) {
                const LayerCounts c = peel(frame, (iteration + 1) % 2, stats);
                if (c.inLayer == 0) return PeelStep{};  // a guard: a non-empty range has a front layer
                resolve(frame, stats);
                return PeelStep{c.inLayer, c.stored, c.overflow};
            });
            composite(frame, stats);
        }
        storage_.endFrame();
        loop.finish();
        // Two RG32F min-max targets (8 B each), front and back accumulations (RGBA16F, 8 B, or
        // RGBA32F, 16 B, each; twice with coloured filters) and the layer storage of both sides.
        const std::uint64_t pixels = std::uint64_t(frame.size.x) * std::uint64_t(frame.size.y);
        stats.bytes = pixels * (2 * 8 + (rgb() ? 4 : 2) * floatTexelBytes(s.precision, 4)) + storage_.bytes();
    }

private:
    bool rgb() const { return model_ == ColorModel::RgbTransmittance; }

    void ensurePrograms(ColorModel model) {
        Programs& p = programs_.use(model);
        if (p.init.program) return;
        p.init = buildSceneProgram("oit/peeling/dual_init.frag.glsl");
        p.peel = buildSceneProgram("oit/peeling/dual_layer_peel.frag.glsl", withColorModel(storage_.defines(), model));
        gl::Defines dual = withColorModel(storage_.defines(), model);
        dual["DUAL"] = "";
        p.resolve = gl::buildProgram({"common/fullscreen.vert.glsl", "oit/peeling/layer_resolve.frag.glsl"}, dual);
        p.composite = buildFullscreenProgram("oit/peeling/peel_composite.frag.glsl", model, {{"DUAL", ""}});
        if (!samples_) samples_ = gl::createQuery(GL_SAMPLES_PASSED);
    }

    void ensureTargets(glm::ivec2 size, int precision, ColorModel model) {
        if (size == size_ && precision == precision_ && model == model_) return;
        size_ = size;
        precision_ = precision;
        model_ = model;
        const GLenum rgba = rgbaFloatFormat(precision);
        for (auto& t : minMax_) t = gl::createTexture2D(GL_RG32F, size.x, size.y);
        frontAccum_ = gl::createTexture2D(rgba, size.x, size.y);
        backAccum_ = gl::createTexture2D(rgba, size.x, size.y);
        std::vector<GLuint> targets = {frontAccum_.id(), backAccum_.id()};
        frontPasses_ = {};
        backPasses_ = {};
        if (rgb()) {
            // layer_resolve.frag.glsl's outputs: front, its passes, back, its passes.
            frontPasses_ = gl::createTexture2D(rgba, size.x, size.y);
            backPasses_ = gl::createTexture2D(rgba, size.x, size.y);
            targets = {frontAccum_.id(), frontPasses_.id(), backAccum_.id(), backPasses_.id()};
        }
        resolveFbo_ = gl::createFramebuffer(targets);
    }

    // minMax_[target] (cleared to the empty range) with the frame's opaque depth, MAX blending.
    // Re-attached on every use: the frame targets replace the opaque depth on a resize.
    void bindRangeTarget(const FrameContext& frame, int target) {
        if (!peelFbo_) peelFbo_ = gl::Framebuffer::create();
        glNamedFramebufferTexture(peelFbo_.id(), GL_COLOR_ATTACHMENT0, minMax_[target].id(), 0);
        glNamedFramebufferTexture(peelFbo_.id(), GL_DEPTH_ATTACHMENT, frame.targets.depth(), 0);
        const float emptyRange[4] = {-2, -2, 0, 0};
        glClearTexImage(minMax_[target].id(), 0, GL_RGBA, GL_FLOAT, emptyRange);
        glBindFramebuffer(GL_FRAMEBUFFER, peelFbo_.id());
        setTransparentDepthState(frame);
        glEnable(GL_BLEND);
        glBlendEquation(GL_MAX);
    }

    std::uint64_t initialise(const FrameContext& frame, TechniqueStats& stats) {
        gl::ScopedPass pass(frame.timer, id_ + " init");
        bindRangeTarget(frame, 0);
        glBeginQuery(GL_SAMPLES_PASSED, samples_.id());
        skipper_.draw(frame, programs_->init, stats);
        glEndQuery(GL_SAMPLES_PASSED);
        glBlendEquation(GL_FUNC_ADD);
        glDisable(GL_BLEND);
        ++stats.passes;
        const std::uint64_t total = gl::queryResult(samples_);
        return total;
    }

    // Stores the layers at both ends of minMax_[1 - cur] and writes the next range to
    // minMax_[cur]; repeated when the list pool had to grow.
    LayerCounts peel(const FrameContext& frame, int cur, TechniqueStats& stats) {
        for (;;) {
            gl::ScopedPass pass(frame.timer, id_ + " peel");
            glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
            bindRangeTarget(frame, cur);
            glBindTextureUnit(gpu::BIND_PEEL_PREVIOUS, minMax_[1 - cur].id());
            storage_.beginPass(programs_->peel.id());
            skipper_.draw(frame, programs_->peel, stats);
            glBlendEquation(GL_FUNC_ADD);
            glDisable(GL_BLEND);
            ++stats.passes;
            const LayerCounts c = storage_.endPass();
            if (!c.repeat) return c;
            ++stats.regrows;
        }
    }

    void resolve(const FrameContext& frame, TechniqueStats& stats) {
        gl::ScopedPass pass(frame.timer, id_ + " resolve");
        glBindFramebuffer(GL_FRAMEBUFFER, resolveFbo_.id());
        glViewport(0, 0, frame.size.x, frame.size.y);
        if (rgb()) {
            // The resolve reads and writes its own texel of all four targets (layer_resolve.frag.glsl).
            bindAccumulations();
            glTextureBarrier();
        } else {
            glEnable(GL_BLEND);
            glBlendEquation(GL_FUNC_ADD);
            glBlendFuncSeparatei(0, GL_DST_ALPHA, GL_ONE, GL_ZERO, GL_ONE_MINUS_SRC_ALPHA);            // under
            glBlendFuncSeparatei(1, GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE_MINUS_SRC_ALPHA);  // over
        }
        storage_.bindForResolve(programs_->resolve.id());
        TransparentAreaScissor scissor(frame);  // nothing was stored outside it: a no-op there
        drawFullscreen(frame, programs_->resolve.id());
        glDisable(GL_BLEND);
        ++stats.passes;
    }

    void composite(const FrameContext& frame, TechniqueStats& stats) {
        gl::ScopedPass pass(frame.timer, id_ + " composite");
        glBindFramebuffer(GL_FRAMEBUFFER, frame.targets.outputFramebuffer());
        glDisable(GL_BLEND);
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
        glBindTextureUnit(gpu::BIND_OPAQUE_COLOR, frame.targets.opaqueColor());
        bindAccumulations();
        TransparentAreaScissor scissor(frame);  // the output holds the opaque colour elsewhere
        drawFullscreen(frame, programs_->composite.id());
        ++stats.passes;
    }

    void bindAccumulations() const {
        glBindTextureUnit(gpu::BIND_PEEL_ACCUM, frontAccum_.id());
        glBindTextureUnit(gpu::BIND_PEEL_BACK_ACCUM, backAccum_.id());
        if (!rgb()) return;
        glBindTextureUnit(gpu::BIND_PEEL_ACCUM_FILTER, frontPasses_.id());
        glBindTextureUnit(gpu::BIND_PEEL_BACK_ACCUM_FILTER, backPasses_.id());
    }

    struct Programs {
        SceneProgram init, peel;
        gl::Program resolve, composite;
    };
    std::string id_;
    LayerStorage storage_;
    ProgramsPerColorModel<Programs> programs_;  // oit/color_model.hpp
    gl::Query samples_;
    glm::ivec2 size_{0, 0};
    int precision_ = 0;
    ColorModel model_ = ColorModel::Scalar;  // the targets'
    gl::Texture minMax_[2], frontAccum_, backAccum_;
    gl::Texture frontPasses_, backPasses_;  // the RGB build's: what each accumulation lets through
    gl::Framebuffer peelFbo_, resolveFbo_;
    ObjectSkipper skipper_;
};

}  // namespace
}  // namespace strata::peeling

namespace strata {

TechniqueEntry dualLlEntry() {
    TechniqueInfo info{"dual-ll", "coplanarity", true, true,
                       "2*ceil(D/2)+2 (init + ceil(D/2) peels + as many resolves + composite; +1 peel per pool "
                       "regrow); Table 1: D",
                       "w*h*48 B at precision=32 (2 RG32F min-max + 2 RGBA32F accumulations) + w*h*8 heads + 24 B "
                       "per fragment of the largest front+back layer pair (pool grown to it); Table 1: "
                       "2C(Zf,Zb)+6 words; + two RGBA targets in a scene with coloured filters",
                       "DUAL-LL: dual peeling whose front and back layers link every fragment within the tie "
                       "tolerance into per-pixel lists (front nodes from the pool's start, back from its end)"};
    info.rgbTransmittance = true;
    return techniqueEntry<peeling::LayerPeelingTechnique<peeling::LayerListSettings, peeling::DualLayers>>(
        info, peeling::LayerStore::List);
}

TechniqueEntry dualFabEntry() {
    TechniqueInfo info{"dual-fab", "coplanarity", false, true,
                       "2*ceil(D/2)+2 (init + ceil(D/2) peels + as many resolves + composite); Table 1: D",
                       "w*h*(48 + 2*(20K + 4)) B at precision=32 (2 RG32F min-max + 2 RGBA32F accumulations, "
                       "K entries + counter per side; + two RGBA targets with coloured filters); Table 1: K+6 words",
                       "DUAL-FAB (DUAL-B): dual peeling keeping up to K coincident fragments per pixel of the front "
                       "and of the back layer in fixed arrays; the rest counted as overflow"};
    info.rgbTransmittance = true;
    return techniqueEntry<peeling::LayerPeelingTechnique<peeling::LayerBufferSettings, peeling::DualLayers>>(
        info, peeling::LayerStore::Fab);
}

}  // namespace strata
