// `dual`: dual depth peeling (Bavoil and Myers 2008), adapted to reversed-Z. An initialisation
// pass finds each pixel's nearest and farthest depth (MAX blending of (z, -z) into RG32F, with
// the hardware depth test only against the opaque depth); each peel pass then extracts the
// front and the back layer at once and finds the next range from the fragments strictly
// between them, and a full-screen pass blends the front layer under the front accumulation and
// the back layer over the back accumulation. ceil(D/2) peel passes: the blend also counts the
// layers and whether any fragment lies strictly inside the next range, and when none does the
// next pass is not issued.
// Coincident fragments at the nearest (farthest) depth merge by MAX: not coplanarity-aware.
// With atomic_range the init and the peel passes find the next range by image atomics instead
// of the RG32F MAX blend, and a full-screen pass after each writes the range in the same form
// (dual_range_pack.frag.glsl), so everything after them reads what it read before; the total
// then comes from a counting pass before the init (f2b_count.frag.glsl).
// With back_depth_test (the default) a peel pass tests against the back of its range instead of
// the opaque depth (which lies behind it), so the back layers peeled already are rejected
// before they are shaded; the shader still decides every fragment near the back
// (dual_back_depth.glsl). Each blend (or atomic_range's pack) writes it on the way. The first
// peel tests against the opaque depth, as the init did: nothing lies behind the first range's
// back, so a depth pass to test against it would reject nothing.
// In a scene with coloured filters (oit/color_model.hpp) the layers carry their filters and both
// accumulations what they let through per channel, in four more targets (dual_blend.frag.glsl).
#include "oit/technique.hpp"

#include "common/bindings.h"
#include "gl/pass_counters.hpp"
#include "oit/color_model.hpp"
#include "oit/draw_transparent.hpp"
#include "oit/peeling/object_skipper.hpp"
#include "oit/peeling/peel_bindings.h"
#include "oit/peeling/peel_loop.hpp"
#include "oit/peeling/peeling_settings.hpp"
#include "oit/precision.hpp"

namespace strata::peeling {
namespace {

class DualPeeling final : public TechniqueWithSettings<DualSettings> {
public:
    using TechniqueWithSettings::TechniqueWithSettings;

    void render(const FrameContext& frame) override {
        const ColorModel model = colorModelFor(frame.scene);
        ensurePrograms(model);
        ensureTargets(frame.size, model);
        PeelLoop loop(frame, stats_, skipper_, settings_.skipPeeled);
        // The last frame's packs reset the range images with image stores: order them before
        // this frame's atomics.
        if (settings_.atomicRange) glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        loop.setTotal(initialise(frame));
        if (loop.total() > 0) {
            clearAccumulation(frontAccum_.id(), rgb() ? frontAccumFilter_.id() : 0);
            clearAccumulation(backAccum_.id(), rgb() ? backAccumFilter_.id() : 0);
            PeelLoopOptions options;
            options.maxPasses = settings_.maxPasses;
            // What is left lies inside the next range, between its nearest and farthest depth.
            options.between = [&](int pass) {
                skipper_.query(frame, minMax_[(pass + 1) % 2].id(),
                               {RemainingSide::NotNearerThanR, RemainingSide::NotFartherThanG});
            };
            // A pass takes at most two fragments a pixel (read_ahead: PeelLoop::runAhead).
            if (settings_.readAhead) options.takenAtMost = 2 * std::uint64_t(frame.size.x) * std::uint64_t(frame.size.y);
            // Pass p peels from minMax_[p % 2] into minMax_[(p + 1) % 2] (the init wrote minMax_[0]).
            loop.runAhead(
                options,
                [&](int pass) {
                    const int cur = (pass + 1) % 2;
                    // The back depth is there after a blend, or after atomic_range's packs.
                    peel(frame, cur, settings_.backDepthTest && (pass > 0 || settings_.atomicRange));
                    // The back depth for the next peel: the pack writes it, or else the blend.
                    if (settings_.atomicRange) packRange(frame, cur);
                    blend(frame, cur, passCounts(pass));
                },
                [&](int pass) { return collect(passCounts(pass)); });
            composite(frame);
        }
        loop.finish();
        std::uint64_t pixels = std::uint64_t(frame.size.x) * frame.size.y;
        // Two RG32F min-max targets (8 B), front and back layers and front and back
        // accumulations (RGBA16F, 8 B, or RGBA32F, 16 B, each).
        // With coloured filters, four more: the layers' filters and the accumulations'.
        stats_.bytes = pixels * (2 * 8 + (rgb() ? 8 : 4) * floatTexelBytes(settings_.precision, 4));
        // atomic_range: two pairs of R32I images (4 B each).
        if (settings_.atomicRange) stats_.bytes += pixels * 4 * 4;
        // back_depth_test: a 32-bit depth buffer.
        if (settings_.backDepthTest) stats_.bytes += pixels * 4;
    }

private:
    bool rgb() const { return model_ == ColorModel::RgbTransmittance; }

    void ensurePrograms(ColorModel model) {
        Programs& p = programs_.use(model);
        if (!p.peel.program) {
            const gl::Defines defines = withColorModel({}, model);
            p.peel = buildSceneProgram("oit/peeling/dual_peel.frag.glsl", defines);
            p.blend = gl::buildProgram({"common/fullscreen.vert.glsl", "oit/peeling/dual_blend.frag.glsl"}, defines);
            p.composite = gl::buildProgram({"common/fullscreen.vert.glsl", "oit/peeling/peel_composite.frag.glsl"},
                                           withColorModel({{"DUAL", ""}}, model));
        }
        // atomic_range's, built when first used.
        if (settings_.atomicRange && !p.peelAtomic.program) {
            gl::Defines atomic = withColorModel({}, model);
            atomic["STRATA_DUAL_ATOMIC_RANGE"] = "";
            p.peelAtomic = buildSceneProgram("oit/peeling/dual_peel.frag.glsl", atomic);
        }
        if (settings_.atomicRange && !packProgram_) {
            packProgram_ = gl::buildProgram({"common/fullscreen.vert.glsl", "oit/peeling/dual_range_pack.frag.glsl"});
            initAtomicProgram_ = buildSceneProgram("oit/peeling/dual_init.frag.glsl", {{"STRATA_DUAL_ATOMIC_RANGE", ""}});
            countProgram_ = buildSceneProgram("oit/peeling/f2b_count.frag.glsl");
        }
        if (initProgram_.program) return;
        initProgram_ = buildSceneProgram("oit/peeling/dual_init.frag.glsl");
        samples_ = gl::createQuery(GL_SAMPLES_PASSED);
    }

    void ensureTargets(glm::ivec2 size, ColorModel model) {
        if (size != size_ || settings_.precision != allocatedPrecision_ || model != model_) {
            size_ = size;
            allocatedPrecision_ = settings_.precision;
            model_ = model;
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
            const GLenum four[4] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2,
                                    GL_COLOR_ATTACHMENT3};
            frontFilter_ = {};
            backFilter_ = {};
            frontAccumFilter_ = {};
            backAccumFilter_ = {};
            if (rgb()) {
                frontFilter_ = gl::createTexture2D(rgba, size.x, size.y);
                backFilter_ = gl::createTexture2D(rgba, size.x, size.y);
                frontAccumFilter_ = gl::createTexture2D(rgba, size.x, size.y);
                backAccumFilter_ = gl::createTexture2D(rgba, size.x, size.y);
                glNamedFramebufferTexture(blendFbo_.id(), GL_COLOR_ATTACHMENT2, frontAccumFilter_.id(), 0);
                glNamedFramebufferTexture(blendFbo_.id(), GL_COLOR_ATTACHMENT3, backAccumFilter_.id(), 0);
            }
            glNamedFramebufferDrawBuffers(blendFbo_.id(), rgb() ? 4 : 2, four);
            for (auto& t : nextNearest_) t = {};
            for (auto& t : nextFarthest_) t = {};
            backDepth_ = {};
        }
        // Each setting's memory is held only while it is on (the bytes count it so).
        if (settings_.backDepthTest && !backDepth_) backDepth_ = gl::createTexture2D(GL_DEPTH_COMPONENT32F, size.x, size.y);
        if (!settings_.backDepthTest) backDepth_ = {};
        if (!settings_.atomicRange)
            for (int i = 0; i < 2; ++i) nextNearest_[i] = {}, nextFarthest_[i] = {};
        if (settings_.atomicRange && !nextNearest_[0]) {
            // Empty (dual_range_images.glsl); each pack resets what it read.
            for (int i = 0; i < 2; ++i) {
                nextNearest_[i] = gl::createTexture2D(GL_R32I, size.x, size.y);
                nextFarthest_[i] = gl::createTexture2D(GL_R32I, size.x, size.y);
                glClearTexImage(nextNearest_[i].id(), 0, GL_RED_INTEGER, GL_INT, &gpu::DUAL_NO_NEAREST);
                glClearTexImage(nextFarthest_[i].id(), 0, GL_RED_INTEGER, GL_INT, &gpu::DUAL_NO_FARTHEST);
            }
        }
    }

    // The peel framebuffer is re-attached on every use: it shares the frame's opaque depth,
    // whose texture the frame targets replace when the size changes. `backTest`: a peel tests
    // against the back of its range, which lies in front of the opaque depth.
    void bindPeelTargets(const FrameContext& frame, int cur, bool withLayers, bool backTest = false) {
        if (!peelFbo_) peelFbo_ = gl::Framebuffer::create();
        GLuint fbo = peelFbo_.id();
        // atomic_range: a peel pass leaves the range in images; packRange writes minMax_[cur].
        const bool rangeTarget = !(withLayers && settings_.atomicRange);
        glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0, rangeTarget ? minMax_[cur].id() : 0, 0);
        glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT1, withLayers ? front_.id() : 0, 0);
        glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT2, withLayers ? back_.id() : 0, 0);
        const bool filters = withLayers && rgb();
        glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT3, filters ? frontFilter_.id() : 0, 0);
        glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT4, filters ? backFilter_.id() : 0, 0);
        glNamedFramebufferTexture(fbo, GL_DEPTH_ATTACHMENT, backTest ? backDepth_.id() : frame.targets.depth(), 0);
        const GLenum five[5] = {rangeTarget ? GLenum(GL_COLOR_ATTACHMENT0) : GLenum(GL_NONE), GL_COLOR_ATTACHMENT1,
                                GL_COLOR_ATTACHMENT2, GL_COLOR_ATTACHMENT3, GL_COLOR_ATTACHMENT4};
        glNamedFramebufferDrawBuffers(fbo, filters ? 5 : withLayers ? 3 : 1, five);
        const float clearRange[4] = {-2, -2, 0, 0};
        if (rangeTarget) glClearTexImage(minMax_[cur].id(), 0, GL_RGBA, GL_FLOAT, clearRange);
        if (withLayers) {
            glClearTexImage(front_.id(), 0, GL_RGBA, GL_FLOAT, nullptr);
            glClearTexImage(back_.id(), 0, GL_RGBA, GL_FLOAT, nullptr);
        }
        if (filters) {
            glClearTexImage(frontFilter_.id(), 0, GL_RGBA, GL_FLOAT, nullptr);
            glClearTexImage(backFilter_.id(), 0, GL_RGBA, GL_FLOAT, nullptr);
        }
        glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        setTransparentDepthState(frame);  // no writes
        if (backTest) glDepthFunc(GL_GEQUAL);  // the back itself passes
        glEnable(GL_BLEND);
        glBlendEquation(GL_MAX);
    }

    std::uint64_t initialise(const FrameContext& frame) {
        if (settings_.atomicRange) return initialiseByAtomics(frame);
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

    // atomic_range: the count (f2b_count.frag.glsl), then the first range by atomics into
    // nextNearest_/nextFarthest_[0], packed into minMax_[0] (with the back depth). The init's
    // MAX blend of every fragment was a fifth to a third of dual's frame on an H200 once the
    // peels used atomics (docs/gpu-h200-session5.md).
    std::uint64_t initialiseByAtomics(const FrameContext& frame) {
        std::uint64_t total = 0;
        {
            gl::ScopedPass pass(frame.timer, "dual count");
            bindPeelTargets(frame, 0, false);
            glDisable(GL_BLEND);
            glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
            glBeginQuery(GL_SAMPLES_PASSED, samples_.id());
            skipper_.draw(frame, countProgram_, stats_);
            glEndQuery(GL_SAMPLES_PASSED);
            ++stats_.passes;
            total = gl::queryResult(samples_);
        }
        if (total == 0) {
            glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
            return 0;
        }
        {
            gl::ScopedPass pass(frame.timer, "dual init");
            // Still the count's framebuffer and state: the opaque depth, nothing written.
            bindRangeImages(0);
            skipper_.draw(frame, initAtomicProgram_, stats_);
            glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
            ++stats_.passes;
        }
        packRange(frame, 0);
        return total;
    }

    // Peels the front and back layers using minMax_[1 - cur]; the next range goes to
    // minMax_[cur]. `backTest`: against the back depth of minMax_[1 - cur] (back_depth_test).
    void peel(const FrameContext& frame, int cur, bool backTest) {
        gl::ScopedPass pass(frame.timer, "dual peel");
        bindPeelTargets(frame, cur, true, backTest);
        glBindTextureUnit(gpu::BIND_PEEL_PREVIOUS, minMax_[1 - cur].id());
        if (settings_.atomicRange) bindRangeImages(cur);
        skipper_.draw(frame, settings_.atomicRange ? programs_->peelAtomic : programs_->peel, stats_);
        glBlendEquation(GL_FUNC_ADD);
        glDisable(GL_BLEND);
        ++stats_.passes;
    }

    // atomic_range: side `side` of the ping-pong's range images (dual_range_images.glsl).
    void bindRangeImages(int side) const {
        glBindImageTexture(gpu::BIND_DUAL_NEXT_NEAREST, nextNearest_[side].id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32I);
        glBindImageTexture(gpu::BIND_DUAL_NEXT_FARTHEST, nextFarthest_[side].id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32I);
    }

    // atomic_range: the range the peel left in nextNearest_/nextFarthest_[cur], written to
    // minMax_[cur] as the MAX blend would have left it; the images are reset for their next use.
    void packRange(const FrameContext& frame, int cur) {
        gl::ScopedPass pass(frame.timer, "dual range pack");
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);  // the peel's atomics
        if (!packFbo_) packFbo_ = gl::Framebuffer::create();
        glNamedFramebufferTexture(packFbo_.id(), GL_COLOR_ATTACHMENT0, minMax_[cur].id(), 0);
        glNamedFramebufferTexture(packFbo_.id(), GL_DEPTH_ATTACHMENT, settings_.backDepthTest ? backDepth_.id() : 0, 0);
        glBindFramebuffer(GL_FRAMEBUFFER, packFbo_.id());
        bindRangeImages(cur);
        drawFullscreenDepth(frame, packProgram_.id());  // every texel, depth written whatever it held
        glDisable(GL_DEPTH_TEST);
        ++stats_.passes;
    }

    // A pass's counts (dual_blend.frag.glsl): its front and back layers' fragments, and the
    // pixels with fragments left strictly inside the next range. One buffer and fence per pass:
    // several may be in flight, and reading one waits for its pass only (gl/pass_counters.hpp).
    gl::PassCounters& passCounts(int pass) {
        while (passCounts_.size() <= std::size_t(pass)) passCounts_.emplace_back();
        return passCounts_[std::size_t(pass)];
    }

    // Blends the layers just peeled and counts them and what is left strictly inside the next
    // range (minMax_[cur]) into `counts`: one full-screen draw (dual_blend.frag.glsl). It was
    // three, each under an occlusion query, at 0.3 ms a draw at 256x256 on llvmpipe; counting
    // with an atomic per fragment had cost more, one per subgroup costs less.
    void blend(const FrameContext& frame, int cur, gl::PassCounters& counts) {
        gl::ScopedPass pass(frame.timer, "dual blend");
        // No memory barrier before it: the peel rendered what this pass samples, which GL orders
        // itself (barriers are for image and buffer stores; on llvmpipe one is a full finish).
        // back_depth_test without atomic_range: the blend writes the next peel's back depth at
        // every pixel, 1 where nothing is left.
        const bool writesBackDepth = settings_.backDepthTest && !settings_.atomicRange;
        glNamedFramebufferTexture(blendFbo_.id(), GL_DEPTH_ATTACHMENT, writesBackDepth ? backDepth_.id() : 0, 0);
        glBindFramebuffer(GL_FRAMEBUFFER, blendFbo_.id());
        glViewport(0, 0, frame.size.x, frame.size.y);
        glEnable(GL_BLEND);
        glBlendEquation(GL_FUNC_ADD);
        if (rgb()) {
            glBlendFunci(0, GL_ONE, GL_ONE);         // front colour += T x layer colour
            glDisablei(GL_BLEND, 1);                 // back: written whole by the shader
            glBlendFunci(2, GL_ZERO, GL_SRC_COLOR);  // front T *= layer filter
            glBlendFunci(3, GL_ZERO, GL_SRC_COLOR);  // back T *= layer filter
            glBindTextureUnit(gpu::BIND_PEEL_LAYER_FILTER, frontFilter_.id());
            glBindTextureUnit(gpu::BIND_PEEL_BACK_FILTER, backFilter_.id());
            glBindTextureUnit(gpu::BIND_PEEL_ACCUM_FILTER, frontAccumFilter_.id());
            glBindTextureUnit(gpu::BIND_PEEL_BACK_ACCUM, backAccum_.id());
            // The draw reads the accumulation texels it writes (ARB_texture_barrier).
            glTextureBarrier();
        } else {
            glBlendFuncSeparatei(0, GL_DST_ALPHA, GL_ONE, GL_ZERO, GL_ONE_MINUS_SRC_ALPHA);                  // under
            glBlendFuncSeparatei(1, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE_MINUS_SRC_ALPHA);  // over
        }
        glBindTextureUnit(gpu::BIND_PEEL_LAYER, front_.id());
        glBindTextureUnit(gpu::BIND_PEEL_BACK, back_.id());
        glBindTextureUnit(gpu::BIND_PEEL_PREVIOUS, minMax_[cur].id());
        counts.reset();
        counts.bind(gpu::BIND_COUNTERS);
        if (writesBackDepth) {
            glEnable(GL_DEPTH_TEST);
            glDepthFunc(GL_ALWAYS);
            glDepthMask(GL_TRUE);
        } else {
            glDisable(GL_DEPTH_TEST);
        }
        {
            // Where nothing transparent lies nothing is blended or counted, and no peel tests
            // the back depth there.
            TransparentAreaScissor scissor(frame);
            drawFullscreenAsSet(frame, programs_->blend.id());
        }
        glDepthMask(GL_FALSE);
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_BLEND);
        counts.fence();
        ++stats_.passes;
    }

    // What a pass's blend counted (waits for it).
    static PeelStep collect(gl::PassCounters& counts) {
        const auto c = counts.read();
        const std::uint64_t taken = std::uint64_t(c[0]) + c[1];
        // A pass that captured nothing had an empty range everywhere, so nothing is left
        // whatever the interior count says (PeelLoop's guard).
        return PeelStep{taken, taken, 0, c[2] != 0};
    }

    void composite(const FrameContext& frame) {
        gl::ScopedPass pass(frame.timer, "dual composite");
        glBindFramebuffer(GL_FRAMEBUFFER, frame.targets.outputFramebuffer());
        glDisable(GL_BLEND);
        glBindTextureUnit(gpu::BIND_OPAQUE_COLOR, frame.targets.opaqueColor());
        glBindTextureUnit(gpu::BIND_PEEL_ACCUM, frontAccum_.id());
        glBindTextureUnit(gpu::BIND_PEEL_BACK_ACCUM, backAccum_.id());
        if (rgb()) {
            glTextureBarrier();
            glBindTextureUnit(gpu::BIND_PEEL_ACCUM_FILTER, frontAccumFilter_.id());
            glBindTextureUnit(gpu::BIND_PEEL_BACK_ACCUM_FILTER, backAccumFilter_.id());
        }
        TransparentAreaScissor scissor(frame);  // the output holds the opaque colour elsewhere
        drawFullscreen(frame, programs_->composite.id());
        ++stats_.passes;
    }

    struct Programs {
        SceneProgram peel, peelAtomic;
        gl::Program blend, composite;
    };
    int allocatedPrecision_ = 0;
    ColorModel model_ = ColorModel::Scalar;  // the targets'
    SceneProgram initProgram_;
    // atomic_range's: the range pack, the init by atomics and the count before it.
    gl::Program packProgram_;
    SceneProgram initAtomicProgram_, countProgram_;
    ProgramsPerColorModel<Programs> programs_;  // oit/color_model.hpp
    gl::Query samples_;                   // the total: the init's count, or atomic_range's count pass's
    std::vector<gl::PassCounters> passCounts_;  // each pass's blend's counts, by pass
    glm::ivec2 size_{0, 0};
    gl::Texture minMax_[2], front_, back_, frontAccum_, backAccum_;
    // The RGB build's: what the layers and the accumulations let through, per channel.
    gl::Texture frontFilter_, backFilter_, frontAccumFilter_, backAccumFilter_;
    // atomic_range: the next range's nearest and farthest depth bits, per side of the ping-pong.
    gl::Texture nextNearest_[2], nextFarthest_[2];
    gl::Texture backDepth_;  // back_depth_test: the back of the range the next peel tests against
    gl::Framebuffer peelFbo_, blendFbo_, packFbo_;
    ObjectSkipper skipper_;
};

}  // namespace
}  // namespace strata::peeling

namespace strata {

TechniqueEntry dualEntry() {
    TechniqueInfo info{"dual", "peeling", true, false,
                       "2*ceil(D/2)+2 (init + ceil(D/2) x (peel, blend) + composite); with atomic_range "
                       "3*ceil(D/2)+4 (count, init, range packs after it and each peel)",
                       "w*h*52 B at precision=16: 2 RG32F min-max (8 each) + 2 layers + 2 accumulations RGBA16F "
                       "(8 each) + the back depth (4, none with back_depth_test off); w*h*84 B at 32 (RGBA32F, 16 "
                       "each); + four more RGBA targets in a scene with coloured filters, + 16 with atomic_range; "
                       "Table 1: 6 words",
                       "dual depth peeling: nearest and farthest layer per pass, MAX-blended min-max depth (or by "
                       "image atomics: atomic_range)"};
    info.rgbTransmittance = true;
    return techniqueEntry<peeling::DualPeeling>(info);
}

}  // namespace strata
