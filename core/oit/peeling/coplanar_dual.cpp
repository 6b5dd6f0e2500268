// `dual-2p`: coplanarity-aware dual depth peeling (depth-fighting paper, section 3.1.2): f2b-2p
// (coplanar_front_to_back.cpp) run from both ends at once. Each iteration peels the front layer
// (anchored at the nearest fragment left) and the back layer (anchored at the farthest), two
// fragments of each in tie order (coplanar_layer.glsl), so up to four fragments an iteration.
//
// Per iteration: counting pass (geometry: per side id min, id max, count and colour sum; the
// next anchors from the fragments between) + check (full screen: per side the pixels with one
// or more and with two or more in two atomic counters, zeroing the colour targets of a side with
// two or more) + extraction (geometry, only where a side holds two or more) + resolve (full
// screen; where no side holds two or more anywhere, a build that reads no id-max fragment and
// no state: llvmpipe would fetch them for every pixel behind a branch). Starts with an
// initialisation pass (MAX/MIN blending: nearest and farthest, the total by GL_SAMPLES_PASSED)
// and ends with peel_composite (DUAL).
//
// In a scene with coloured filters (oit/color_model.hpp) every colour target gains a second
// one (coplanar_layer.glsl), and the resolve draws the two sides apart (twelve targets in all,
// more than GL guarantees one draw: coplanar_dual_resolve.frag.glsl).
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

#include <array>

namespace strata::peeling {
namespace {

// One side's targets: the units of peel_bindings.h, plus BIND_COPLANAR_BACK_OFFSET at the back.
struct Side {
    gl::Texture state, count, minColor, maxColor, layer, accum;
    gl::Texture minOpacity, maxOpacity, layerPasses, accumPasses;  // the RGB build's second texels
};

class CoplanarDual final : public TechniqueWithSettings<PeelingSettings> {
public:
    using TechniqueWithSettings::TechniqueWithSettings;

    void render(const FrameContext& frame) override {
        const ColorModel model = colorModelFor(frame.scene);
        ensurePrograms(model);
        ensureTargets(frame.size, model);
        PeelLoop loop(frame, stats_, skipper_, settings_.skipPeeled);
        if (!ids_.bind(frame)) stats_.overflowed = true;
        for (const gl::Framebuffer* fbo : {&initFbo_, &countFbo_, &extractFbo_})
            glNamedFramebufferTexture(fbo->id(), GL_DEPTH_ATTACHMENT, frame.targets.depth(), 0);
        const float frontClear[4] = {-1.0f, 0.0f, -kNoId, 0.0f};
        const float backClear[4] = {2.0f, 0.0f, -kNoId, 0.0f};  // MIN-blended by the init
        const float nothingLeft[4] = {-1.0f, -2.0f, 0.0f, 0.0f};
        glClearTexImage(side_[0].state.id(), 0, GL_RGBA, GL_FLOAT, frontClear);
        glClearTexImage(side_[1].state.id(), 0, GL_RGBA, GL_FLOAT, backClear);
        for (Side& s : side_) {
            clearAccumulation(s.accum.id(), rgb() ? s.accumPasses.id() : 0);
            clearAccumulation(s.layer.id(), rgb() ? s.layerPasses.id() : 0);
        }
        layerOpen_ = false;  // cleared above: none open until an iteration leaves one
        glClearTexImage(bound_.id(), 0, GL_RGBA, GL_FLOAT, nothingLeft);
        setDepthOrderUniforms(frame, programs_->count.id());
        setDepthOrderUniforms(frame, programs_->extract.id());

        loop.setTotal(initialise(frame));
        if (loop.total() > 0) {
            PeelLoopOptions options;
            options.maxPasses = settings_.maxPasses;
            // What is left lies between the two sides' layers just resolved (the skip bound).
            options.between = [&](int) {
                skipper_.query(frame, bound_.id(), {RemainingSide::NotNearerThanR, RemainingSide::NotFartherThanG});
            };
            // Both sides' layers are captured whole, coplanar fragments included.
            loop.run(options, [&](int) {
                count(frame);
                const Checked c = check(frame);
                if (c.coplanar > 0) extract(frame);
                resolve(frame, c.coplanar > 0);
                return PeelStep{c.coplanar + c.any, c.coplanar + c.any};
            });
        }
        if (stats_.fragmentsCaptured > 0) composite(frame);
        loop.finish();
        const std::uint64_t pixels = std::uint64_t(frame.size.x) * frame.size.y;
        // Per side: state and count RGBA32F (16 B each), min and max colour, layer part and
        // accumulation (RGBA16F, 8 B, or RGBA32F, 16 B, each), as many again with coloured
        // filters; the skip bound RG32F (8 B).
        stats_.bytes =
            pixels * (2 * (2 * 16 + (rgb() ? 8 : 4) * floatTexelBytes(settings_.precision, 4)) + 8);
    }

private:
    // The resolve's builds (coplanar_dual_resolve.frag.glsl).
    enum ResolveBuild { kFullResolve, kOnePerSide, kOnePerSideNoOpenLayer, kResolveBuilds };

    struct Checked {
        std::uint64_t any = 0;       // pixel-sides with one or more counted
        std::uint64_t coplanar = 0;  // pixel-sides with two or more
    };

    bool rgb() const { return model_ == ColorModel::RgbTransmittance; }

    void ensurePrograms(ColorModel model) {
        Programs& p = programs_.use(model);
        if (p.init.program) return;
        auto fullscreen = [model](const char* fragment, gl::Defines defines = {}) {
            return buildFullscreenProgram(fragment, model, std::move(defines));
        };
        p.init = buildSceneProgram("oit/peeling/coplanar_init.frag.glsl");
        p.count = buildSceneProgram("oit/peeling/coplanar_dual_count.frag.glsl", withColorModel({}, model));
        p.extract = buildSceneProgram("oit/peeling/coplanar_dual_extract.frag.glsl", withColorModel({}, model));
        p.check = fullscreen("oit/peeling/coplanar_dual_check.frag.glsl");
        // Each as three builds: the full one, one for an iteration where no side holds two or more
        // (ONE_PER_SIDE), and one for such an iteration before any layer part was left open.
        const gl::Defines builds[kResolveBuilds] = {
            {}, {{"ONE_PER_SIDE", ""}}, {{"ONE_PER_SIDE", ""}, {"NO_OPEN_LAYER", ""}}};
        for (int b = 0; b < kResolveBuilds; ++b) {
            gl::Program* resolve = p.resolve[b];
            auto with = [&](const char* side) {
                gl::Defines d = builds[b];
                if (side) d[side] = "";
                return d;
            };
            if (model == ColorModel::RgbTransmittance) {
                resolve[0] = fullscreen("oit/peeling/coplanar_dual_resolve.frag.glsl", with("RESOLVE_FRONT"));
                resolve[1] = fullscreen("oit/peeling/coplanar_dual_resolve.frag.glsl", with("RESOLVE_BACK"));
            } else {
                resolve[0] = fullscreen("oit/peeling/coplanar_dual_resolve.frag.glsl", with(nullptr));
            }
        }
        p.composite = fullscreen("oit/peeling/peel_composite.frag.glsl", {{"DUAL", ""}});
        if (!samples_) samples_ = gl::createQuery(GL_SAMPLES_PASSED);
    }

    void ensureTargets(glm::ivec2 size, ColorModel model) {
        if (size == size_ && settings_.precision == allocatedPrecision_ && model == model_) return;
        size_ = size;
        allocatedPrecision_ = settings_.precision;
        model_ = model;
        const GLenum rgba = rgbaFloatFormat(settings_.precision);
        for (Side& s : side_) {
            s.state = gl::createTexture2D(GL_RGBA32F, size.x, size.y);
            s.count = gl::createTexture2D(GL_RGBA32F, size.x, size.y);
            s.minColor = gl::createTexture2D(rgba, size.x, size.y);
            s.maxColor = gl::createTexture2D(rgba, size.x, size.y);
            s.layer = gl::createTexture2D(rgba, size.x, size.y);
            s.accum = gl::createTexture2D(rgba, size.x, size.y);
            for (gl::Texture* t : {&s.minOpacity, &s.maxOpacity, &s.layerPasses, &s.accumPasses}) *t = {};
            if (!rgb()) continue;
            s.minOpacity = gl::createTexture2D(rgba, size.x, size.y);
            s.maxOpacity = gl::createTexture2D(rgba, size.x, size.y);
            s.layerPasses = gl::createTexture2D(rgba, size.x, size.y);
            s.accumPasses = gl::createTexture2D(rgba, size.x, size.y);
        }
        // The check zeroes a side's targets as dst x 0 (a blend that keeps the other side), and
        // only the extraction writes the max ones: new storage is undefined, and a NaN in it
        // would survive x 0. The min ones are cleared by every counting pass.
        for (Side& s : side_)
            for (const gl::Texture* t : {&s.maxColor, &s.maxOpacity})
                if (*t) glClearTexImage(t->id(), 0, GL_RGBA, GL_FLOAT, nullptr);
        bound_ = gl::createTexture2D(GL_RG32F, size.x, size.y);
        const Side &f = side_[0], &b = side_[1];
        initFbo_ = gl::createFramebuffer({f.state.id(), b.state.id()});
        // The RGB build's second texels follow the first ones, in the shaders' output locations.
        if (!rgb()) {
            countFbo_ = gl::createFramebuffer({f.count.id(), b.count.id(), f.minColor.id(), b.minColor.id()});
            extractFbo_ = gl::createFramebuffer({f.minColor.id(), f.maxColor.id(), b.minColor.id(), b.maxColor.id()});
            resolveFbo_[0] = gl::createFramebuffer({f.accum.id(), f.layer.id(), b.accum.id(), b.layer.id(), f.state.id(),
                                          b.state.id(), bound_.id()});
            resolveFbo_[1] = {};
            return;
        }
        countFbo_ = gl::createFramebuffer(
            {f.count.id(), b.count.id(), f.minColor.id(), b.minColor.id(), f.minOpacity.id(), b.minOpacity.id()});
        extractFbo_ = gl::createFramebuffer({f.minColor.id(), f.maxColor.id(), b.minColor.id(), b.maxColor.id(),
                                   f.minOpacity.id(), f.maxOpacity.id(), b.minOpacity.id(), b.maxOpacity.id()});
        resolveFbo_[0] =
            gl::createFramebuffer({f.accum.id(), f.layer.id(), f.state.id(), f.accumPasses.id(), f.layerPasses.id()});
        resolveFbo_[1] = gl::createFramebuffer(
            {b.accum.id(), b.layer.id(), b.state.id(), b.accumPasses.id(), b.layerPasses.id(), bound_.id()});
    }

    void bindTextures() {
        for (int i = 0; i < 2; ++i) {
            const GLuint offset = i == 0 ? 0 : gpu::BIND_COPLANAR_BACK_OFFSET;
            const Side& s = side_[i];
            glBindTextureUnit(gpu::BIND_COPLANAR_STATE + offset, s.state.id());
            glBindTextureUnit(gpu::BIND_COPLANAR_COUNT + offset, s.count.id());
            glBindTextureUnit(gpu::BIND_COPLANAR_MIN_COLOR + offset, s.minColor.id());
            glBindTextureUnit(gpu::BIND_COPLANAR_MAX_COLOR + offset, s.maxColor.id());
            glBindTextureUnit(gpu::BIND_COPLANAR_LAYER + offset, s.layer.id());
            glBindTextureUnit(gpu::BIND_COPLANAR_ACCUM + offset, s.accum.id());
            if (!rgb()) continue;
            glBindTextureUnit(gpu::BIND_COPLANAR_MIN_OPACITY + offset, s.minOpacity.id());
            glBindTextureUnit(gpu::BIND_COPLANAR_MAX_OPACITY + offset, s.maxOpacity.id());
            glBindTextureUnit(gpu::BIND_COPLANAR_LAYER_PASSES + offset, s.layerPasses.id());
            glBindTextureUnit(gpu::BIND_COPLANAR_ACCUM_PASSES + offset, s.accumPasses.id());
        }
    }

    std::uint64_t initialise(const FrameContext& frame) {
        gl::ScopedPass pass(frame.timer, "dual-2p init");
        glBindFramebuffer(GL_FRAMEBUFFER, initFbo_.id());
        setTransparentDepthState(frame);
        glEnable(GL_BLEND);
        glBlendEquationi(0, GL_MAX);
        glBlendEquationi(1, GL_MIN);
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

    void count(const FrameContext& frame) {
        gl::ScopedPass pass(frame.timer, "dual-2p count");
        const float countClear[4] = {kNoId, kNoId, kNoId, 0.0f};
        for (Side& s : side_) {
            glClearTexImage(s.count.id(), 0, GL_RGBA, GL_FLOAT, countClear);
            glClearTexImage(s.minColor.id(), 0, GL_RGBA, GL_FLOAT, nullptr);
            if (rgb()) glClearTexImage(s.minOpacity.id(), 0, GL_RGBA, GL_FLOAT, nullptr);
        }
        glBindFramebuffer(GL_FRAMEBUFFER, countFbo_.id());
        setTransparentDepthState(frame);
        bindTextures();
        glEnable(GL_BLEND);
        glBlendFunc(GL_ONE, GL_ONE);
        glBlendEquationSeparatei(0, GL_MAX, GL_FUNC_ADD);
        glBlendEquationSeparatei(1, GL_MAX, GL_FUNC_ADD);
        for (GLuint sum = 2; sum < 6; ++sum) glBlendEquationi(sum, GL_FUNC_ADD);  // colour (and opacity) sums
        skipper_.draw(frame, programs_->count, stats_);
        glBlendEquation(GL_FUNC_ADD);
        glBlendFunc(GL_ONE, GL_ZERO);
        glDisable(GL_BLEND);
        ++stats_.passes;
    }

    Checked check(const FrameContext& frame) {
        gl::ScopedPass pass(frame.timer, "dual-2p check");
        glBindFramebuffer(GL_FRAMEBUFFER, extractFbo_.id());
        glViewport(0, 0, frame.size.x, frame.size.y);
        // Zero (src alpha 1) or keep (0) each target: dst x (1 - src alpha), colour and alpha.
        glEnable(GL_BLEND);
        glBlendEquation(GL_FUNC_ADD);
        glBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE_MINUS_SRC_ALPHA);
        bindTextures();
        checkCounters_.reset();
        checkCounters_.bind(gpu::BIND_COUNTERS);
        {
            TransparentAreaScissor scissor(frame);  // nothing was counted outside it: a no-op there
            drawFullscreen(frame, programs_->check.id());
        }
        checkCounters_.fence();
        glBlendFunc(GL_ONE, GL_ZERO);
        glDisable(GL_BLEND);
        ++stats_.passes;
        const auto counts = checkCounters_.read();
        return Checked{counts[1], counts[0]};
    }

    void extract(const FrameContext& frame) {
        gl::ScopedPass pass(frame.timer, "dual-2p extract");
        glBindFramebuffer(GL_FRAMEBUFFER, extractFbo_.id());
        setTransparentDepthState(frame);
        bindTextures();
        glEnable(GL_BLEND);
        glBlendEquation(GL_MAX);
        skipper_.draw(frame, programs_->extract, stats_);
        glBlendEquation(GL_FUNC_ADD);
        glDisable(GL_BLEND);
        ++stats_.passes;
    }

    // anyCoplanar: whether the check found a side holding two or more anywhere.
    void resolve(const FrameContext& frame, bool anyCoplanar) {
        const int build = anyCoplanar ? kFullResolve : (layerOpen_ ? kOnePerSide : kOnePerSideNoOpenLayer);
        if (anyCoplanar) layerOpen_ = true;  // where three or more were left, a layer part stays open
        gl::ScopedPass pass(frame.timer, "dual-2p resolve");
        glViewport(0, 0, frame.size.x, frame.size.y);
        glDisable(GL_BLEND);
        bindTextures();
        TransparentAreaScissor scissor(frame);  // nothing was counted outside it: a no-op there
        // Each draw reads its own texel of its attachments; the RGB build's back draw, the
        // state its front draw wrote.
        // NO_OPEN_LAYER leaves the layer parts their clear, the empty partial. Their draw
        // buffers: 1 and 3 in the one draw, 1 and 4 (their passes) in each RGB draw.
        std::vector<GLuint> layerParts;
        if (build == kOnePerSideNoOpenLayer) layerParts = {1, rgb() ? 4u : 3u};
        for (int draw = 0; draw < (rgb() ? 2 : 1); ++draw) {
            glBindFramebuffer(GL_FRAMEBUFFER, resolveFbo_[draw].id());
            glTextureBarrier();
            MaskedDrawBuffers keep(layerParts);
            drawFullscreen(frame, programs_->resolve[build][draw].id());
        }
        ++stats_.passes;
    }

    void composite(const FrameContext& frame) {
        gl::ScopedPass pass(frame.timer, "dual-2p composite");
        glBindFramebuffer(GL_FRAMEBUFFER, frame.targets.outputFramebuffer());
        glDisable(GL_BLEND);
        glBindTextureUnit(gpu::BIND_OPAQUE_COLOR, frame.targets.opaqueColor());
        glBindTextureUnit(gpu::BIND_PEEL_ACCUM, side_[0].accum.id());
        glBindTextureUnit(gpu::BIND_PEEL_BACK_ACCUM, side_[1].accum.id());
        if (rgb()) {
            glBindTextureUnit(gpu::BIND_PEEL_ACCUM_FILTER, side_[0].accumPasses.id());
            glBindTextureUnit(gpu::BIND_PEEL_BACK_ACCUM_FILTER, side_[1].accumPasses.id());
        }
        TransparentAreaScissor scissor(frame);  // the output holds the opaque colour elsewhere
        drawFullscreen(frame, programs_->composite.id());
        ++stats_.passes;
    }

    struct Programs {
        SceneProgram init, count, extract;
        // resolve[build][1]: the RGB build's back-side draw
        gl::Program check, resolve[kResolveBuilds][2], composite;
    };
    int allocatedPrecision_ = 0;
    ColorModel model_ = ColorModel::Scalar;  // the targets'
    ProgramsPerColorModel<Programs> programs_;  // oit/color_model.hpp
    gl::Query samples_;
    gl::PassCounters checkCounters_;  // sides with two or more, sides with one or more
    bool layerOpen_ = false;          // this frame: a full resolve ran, so a layer part may be open
    glm::ivec2 size_{0, 0};
    Side side_[2];
    gl::Texture bound_;
    gl::Framebuffer initFbo_, countFbo_, extractFbo_, resolveFbo_[2];
    CoplanarIds ids_;
    ObjectSkipper skipper_;
};

}  // namespace
}  // namespace strata::peeling

namespace strata {

TechniqueEntry dual2pEntry() {
    TechniqueInfo info{"dual-2p", "coplanarity", true, true,
                       "1 + iterations x (count, check, resolve; +1 extraction where a side holds C >= 2) + 1, "
                       "a layer from each end per iteration; no coplanarity: 3*ceil(D/2)+2; Table 1: C(Zall)/2+1",
                       "w*h*136 B at precision=16: per side state and count RGBA32F (16 each) + min, max, layer "
                       "and accumulation RGBA16F (8 each), skip bound RG32F (8); w*h*200 B at 32; + four more "
                       "RGBA targets per side in a scene with coloured filters; Table 1: 24 words (20 modern)",
                       "coplanarity-aware dual peeling: Algorithm 1 from both ends, up to four fragments per "
                       "iteration in tie order"};
    info.rgbTransmittance = true;
    return techniqueEntry<peeling::CoplanarDual>(info);
}

}  // namespace strata
