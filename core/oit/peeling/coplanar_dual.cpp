// `dual-2p`: coplanarity-aware dual depth peeling (depth-fighting paper, section 3.1.2): f2b-2p
// (coplanar_front_to_back.cpp) run from both ends at once. Each iteration peels the front layer
// (anchored at the nearest fragment left) and the back layer (anchored at the farthest), two
// fragments of each in tie order (coplanar_layer.glsl), so up to four fragments an iteration.
//
// Per iteration: counting pass (geometry: per side id min, id max, count and colour sum; the
// next anchors from the fragments between) + four check draws (full screen, occlusion queries:
// per side the pixels with one or more and with two or more, the latter zeroing the colour
// targets) + extraction (geometry, only where a side holds two or more) + resolve (full
// screen). Starts with an initialisation pass (MAX/MIN blending: nearest and farthest, the
// total by GL_SAMPLES_PASSED) and ends with peel_composite (DUAL).
#include "oit/technique.hpp"

#include "common/bindings.h"
#include "oit/draw_transparent.hpp"
#include "oit/peeling/coplanar_ids.hpp"
#include "oit/peeling/object_skipper.hpp"
#include "oit/peeling/peel_bindings.h"
#include "oit/peeling/peeling_settings.hpp"
#include "oit/precision.hpp"

namespace strata::peeling {
namespace {

// One side's targets: the units of peel_bindings.h, plus BIND_COPLANAR_BACK_OFFSET at the back.
struct Side {
    gl::Texture state, count, minColor, maxColor, layer, accum;
};

class CoplanarDual final : public TechniqueWithSettings<PeelingSettings> {
public:
    using TechniqueWithSettings::TechniqueWithSettings;

    void render(const FrameContext& frame) override {
        ensurePrograms();
        ensureTargets(frame.size);
        stats_ = {};
        if (!ids_.bind(frame)) stats_.overflowed = true;
        skipper_.beginFrame(frame, settings_.skipPeeled);
        for (const gl::Framebuffer* fbo : {&initFbo_, &countFbo_, &extractFbo_})
            glNamedFramebufferTexture(fbo->id(), GL_DEPTH_ATTACHMENT, frame.targets.depth(), 0);
        const float frontClear[4] = {-1.0f, 0.0f, -kNoId, 0.0f};
        const float backClear[4] = {2.0f, 0.0f, -kNoId, 0.0f};  // MIN-blended by the init
        const float empty[4] = {0, 0, 0, 1};
        const float nothingLeft[4] = {-1.0f, -2.0f, 0.0f, 0.0f};
        glClearTexImage(side_[0].state.id(), 0, GL_RGBA, GL_FLOAT, frontClear);
        glClearTexImage(side_[1].state.id(), 0, GL_RGBA, GL_FLOAT, backClear);
        for (Side& s : side_) {
            glClearTexImage(s.accum.id(), 0, GL_RGBA, GL_FLOAT, empty);
            glClearTexImage(s.layer.id(), 0, GL_RGBA, GL_FLOAT, empty);
        }
        glClearTexImage(bound_.id(), 0, GL_RGBA, GL_FLOAT, nothingLeft);
        setDepthOrderUniforms(frame, countProgram_.id());
        setDepthOrderUniforms(frame, extractProgram_.id());

        const std::uint64_t total = initialise(frame);
        for (int iteration = 0; total > 0; ++iteration) {
            if (iteration >= settings_.maxPasses) {
                stats_.overflowed = true;
                break;
            }
            count(frame);
            const Checked c = check(frame);
            if (c.coplanar > 0) extract(frame);
            resolve(frame);
            const std::uint64_t captured = c.coplanar + c.any;
            stats_.fragmentsCaptured += captured;
            if (stats_.fragmentsCaptured >= total || captured == 0) break;
            skipper_.query(frame, bound_.id(), {RemainingSide::NotNearerThanR, RemainingSide::NotFartherThanG});
        }
        if (stats_.fragmentsCaptured > 0) composite(frame);
        skipper_.endFrame(stats_);
        stats_.fragmentsDropped = total - std::min(total, stats_.fragmentsCaptured);
        const std::uint64_t pixels = std::uint64_t(frame.size.x) * frame.size.y;
        // Per side: state and count RGBA32F (16 B each), min and max colour, layer part and
        // accumulation (RGBA16F, 8 B, or RGBA32F, 16 B, each); the skip bound RG32F (8 B).
        stats_.bytes = pixels * (2 * (2 * 16 + 4 * floatTexelBytes(settings_.precision, 4)) + 8);
    }

private:
    struct Checked {
        std::uint64_t any = 0;       // pixel-sides with one or more counted
        std::uint64_t coplanar = 0;  // pixel-sides with two or more
    };

    void ensurePrograms() {
        if (initProgram_.program) return;
        initProgram_ = buildSceneProgram("oit/peeling/coplanar_init.frag.glsl");
        countProgram_ = buildSceneProgram("oit/peeling/coplanar_dual_count.frag.glsl");
        extractProgram_ = buildSceneProgram("oit/peeling/coplanar_dual_extract.frag.glsl");
        checkProgram_ = gl::buildProgram({"common/fullscreen.vert.glsl", "oit/peeling/coplanar_dual_check.frag.glsl"});
        resolveProgram_ = gl::buildProgram({"common/fullscreen.vert.glsl", "oit/peeling/coplanar_dual_resolve.frag.glsl"});
        compositeProgram_ = gl::buildProgram({"common/fullscreen.vert.glsl", "oit/peeling/peel_composite.frag.glsl"},
                                             {{"DUAL", ""}});
        sideLocation_ = glGetUniformLocation(checkProgram_.id(), "uSide");
        minCountLocation_ = glGetUniformLocation(checkProgram_.id(), "uMinCount");
        samples_ = gl::createQuery(GL_SAMPLES_PASSED);
    }

    static gl::Framebuffer framebuffer(const std::vector<GLuint>& colors) {
        gl::Framebuffer fbo = gl::Framebuffer::create();
        std::vector<GLenum> buffers;
        for (std::size_t i = 0; i < colors.size(); ++i) {
            glNamedFramebufferTexture(fbo.id(), GLenum(GL_COLOR_ATTACHMENT0 + i), colors[i], 0);
            buffers.push_back(GLenum(GL_COLOR_ATTACHMENT0 + i));
        }
        glNamedFramebufferDrawBuffers(fbo.id(), GLsizei(buffers.size()), buffers.data());
        return fbo;
    }

    void ensureTargets(glm::ivec2 size) {
        if (size == size_ && settings_.precision == allocatedPrecision_) return;
        size_ = size;
        allocatedPrecision_ = settings_.precision;
        const GLenum rgba = rgbaFloatFormat(settings_.precision);
        for (Side& s : side_) {
            s.state = gl::createTexture2D(GL_RGBA32F, size.x, size.y);
            s.count = gl::createTexture2D(GL_RGBA32F, size.x, size.y);
            s.minColor = gl::createTexture2D(rgba, size.x, size.y);
            s.maxColor = gl::createTexture2D(rgba, size.x, size.y);
            s.layer = gl::createTexture2D(rgba, size.x, size.y);
            s.accum = gl::createTexture2D(rgba, size.x, size.y);
        }
        bound_ = gl::createTexture2D(GL_RG32F, size.x, size.y);
        const Side &f = side_[0], &b = side_[1];
        initFbo_ = framebuffer({f.state.id(), b.state.id()});
        countFbo_ = framebuffer({f.count.id(), b.count.id(), f.minColor.id(), b.minColor.id()});
        extractFbo_ = framebuffer({f.minColor.id(), f.maxColor.id(), b.minColor.id(), b.maxColor.id()});
        resolveFbo_ = framebuffer({f.accum.id(), f.layer.id(), b.accum.id(), b.layer.id(), f.state.id(), b.state.id(),
                                   bound_.id()});
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
        skipper_.draw(frame, initProgram_, stats_);
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
        }
        glBindFramebuffer(GL_FRAMEBUFFER, countFbo_.id());
        setTransparentDepthState(frame);
        bindTextures();
        glEnable(GL_BLEND);
        glBlendFunc(GL_ONE, GL_ONE);
        glBlendEquationSeparatei(0, GL_MAX, GL_FUNC_ADD);
        glBlendEquationSeparatei(1, GL_MAX, GL_FUNC_ADD);
        glBlendEquationi(2, GL_FUNC_ADD);
        glBlendEquationi(3, GL_FUNC_ADD);
        skipper_.draw(frame, countProgram_, stats_);
        glBlendEquation(GL_FUNC_ADD);
        glBlendFunc(GL_ONE, GL_ZERO);
        glDisable(GL_BLEND);
        ++stats_.passes;
    }

    Checked check(const FrameContext& frame) {
        gl::ScopedPass pass(frame.timer, "dual-2p check");
        glBindFramebuffer(GL_FRAMEBUFFER, extractFbo_.id());
        glViewport(0, 0, frame.size.x, frame.size.y);
        glDisable(GL_BLEND);
        bindTextures();
        const GLuint program = checkProgram_.id();
        Checked c;
        for (int side = 0; side < 2; ++side) {
            for (int minCount : {2, 1}) {
                // Two or more: zero this side's two colour targets there. One or more: count only.
                for (GLuint buffer = 0; buffer < 4; ++buffer) {
                    const GLboolean write = minCount == 2 && int(buffer / 2) == side;
                    glColorMaski(buffer, write, write, write, write);
                }
                glProgramUniform1i(program, sideLocation_, side);
                glProgramUniform1f(program, minCountLocation_, float(minCount));
                glBeginQuery(GL_SAMPLES_PASSED, samples_.id());
                drawFullscreen(frame, program);
                glEndQuery(GL_SAMPLES_PASSED);
                (minCount == 2 ? c.coplanar : c.any) += gl::queryResult(samples_);
            }
        }
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        ++stats_.passes;
        return c;
    }

    void extract(const FrameContext& frame) {
        gl::ScopedPass pass(frame.timer, "dual-2p extract");
        glBindFramebuffer(GL_FRAMEBUFFER, extractFbo_.id());
        setTransparentDepthState(frame);
        bindTextures();
        glEnable(GL_BLEND);
        glBlendEquation(GL_MAX);
        skipper_.draw(frame, extractProgram_, stats_);
        glBlendEquation(GL_FUNC_ADD);
        glDisable(GL_BLEND);
        ++stats_.passes;
    }

    void resolve(const FrameContext& frame) {
        gl::ScopedPass pass(frame.timer, "dual-2p resolve");
        glBindFramebuffer(GL_FRAMEBUFFER, resolveFbo_.id());
        glViewport(0, 0, frame.size.x, frame.size.y);
        glDisable(GL_BLEND);
        bindTextures();
        glTextureBarrier();  // it reads its own texel of six of its attachments
        drawFullscreen(frame, resolveProgram_.id());
        ++stats_.passes;
    }

    void composite(const FrameContext& frame) {
        gl::ScopedPass pass(frame.timer, "dual-2p composite");
        glBindFramebuffer(GL_FRAMEBUFFER, frame.targets.outputFramebuffer());
        glDisable(GL_BLEND);
        glBindTextureUnit(gpu::BIND_OPAQUE_COLOR, frame.targets.opaqueColor());
        glBindTextureUnit(gpu::BIND_PEEL_ACCUM, side_[0].accum.id());
        glBindTextureUnit(gpu::BIND_PEEL_BACK_ACCUM, side_[1].accum.id());
        drawFullscreen(frame, compositeProgram_.id());
        ++stats_.passes;
    }

    int allocatedPrecision_ = 0;
    SceneProgram initProgram_, countProgram_, extractProgram_;
    gl::Program checkProgram_, resolveProgram_, compositeProgram_;
    GLint sideLocation_ = -1, minCountLocation_ = -1;
    gl::Query samples_;
    glm::ivec2 size_{0, 0};
    Side side_[2];
    gl::Texture bound_;
    gl::Framebuffer initFbo_, countFbo_, extractFbo_, resolveFbo_;
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
                       "and accumulation RGBA16F (8 each), skip bound RG32F (8); w*h*200 B at 32; Table 1: 24 "
                       "words (20 modern)",
                       "coplanarity-aware dual peeling: Algorithm 1 from both ends, up to four fragments per "
                       "iteration in tie order"};
    return techniqueEntry<peeling::CoplanarDual>(info);
}

}  // namespace strata
