// `f2b-ll`, `f2b-fab`, `f2b-kb`: front-to-back peeling that captures every coincident fragment
// of a layer (depth-fighting paper, Algorithm 2 F2B-LL and Algorithm 3 F2B-B). A layer is every
// fragment not yet peeled within the tie tolerance of its anchor, the nearest one left
// (layer_tie.glsl: the project's tie rule, not bit-equal depths).
//   1. a depth pass (geometry; next_layer.frag.glsl) anchors the first layer at each pixel's
//      nearest fragment, keeping its colour and ids as f2b keeps its layer, and counts every
//      fragment;
//   2. per layer: a full-screen pass writes the far edge of the layer's band as depth
//      (layer_band.frag.glsl); a capture pass (geometry; layer_capture.frag.glsl), depth-tested
//      against it before its shader runs, stores the layer's fragments other than the anchor in
//      per-pixel storage (layer_storage.hpp: linked lists whose pool grows to the layer for
//      f2b-ll, robust; K - 1 entries per pixel beside the anchor for f2b-fab and f2b-kb,
//      bounded, the rest of the layer counted as overflow); a full-screen resolve composites
//      the anchor and the stored fragments in object, then primitive order under the
//      accumulation (its samples-passed count is the number of anchors); and, unless nothing is
//      left, an anchor pass (geometry; layer_peel.frag.glsl: f2b's peel under the tie rule, no
//      buffer stores) anchors the next layer.
//   Where nothing coincides the capture pass rejects everything in its early depth test and
//   stores nothing, so a layer costs f2b's peel and blend plus two cheap passes.
// Then one composite over the opaque colour. Each capture counts the layer's fragments beside
// its anchors (stored or not), so the loop ends on the layer that leaves nothing.
//
// In a scene with coloured filters (oit/color_model.hpp) the anchors and the storage keep a
// glass fragment's coloured filter (oit/packed_color.glsl) and the accumulation gains a second
// target, what it lets through per channel, which the resolve reads and writes at its own texel.
#include "oit/technique.hpp"

#include "common/bindings.h"
#include "oit/color_model.hpp"
#include "oit/draw_transparent.hpp"
#include "oit/peeling/layer_settings.hpp"
#include "oit/peeling/layer_bindings.h"
#include "oit/peeling/layer_storage.hpp"
#include "oit/peeling/object_skipper.hpp"
#include "oit/peeling/peel_bindings.h"
#include "oit/peeling/peel_loop.hpp"
#include "oit/precision.hpp"

namespace strata::peeling {
namespace {

class FrontToBackLayers {
public:
    FrontToBackLayers(const std::string& id, LayerStore kind) : id_(id), storage_(kind, id) {}

    void render(const FrameContext& frame, const LayerPeelingSettings& s, TechniqueStats& stats) {
        const ColorModel model = colorModelFor(frame.scene);
        ensurePrograms(model);
        ensureTargets(frame.size, s.precision, model);
        PeelLoop loop(frame, stats, skipper_, s.skipPeeled);
        // The anchor is one of the K a bounded layer keeps.
        storage_.prepare(frame.size, 1, s.capacity - 1, s.maxBlockMiB);
        clearAccumulation(accum_.id(), rgb() ? accumPasses_.id() : 0);
        for (GLuint p : {programs_->anchor.id(), programs_->capture.id(), programs_->band.id()})
            setDepthOrderUniforms(frame, p);

        loop.setTotal(firstDepthPass(frame, stats));
        bool composited = false;
        if (loop.total() > 0) {
            // Layer i is anchored in depth_[i % 3] and anchor_[i % 2]; its capture also reads the
            // previous layer's anchor depth.
            PeelLoopOptions options;
            options.maxPasses = s.maxPasses;
            options.between = [&](int layer) {
                const int cur = layer % 3;
                // What is left lies behind this layer's anchor, by more than the tie band: the
                // bound f2b uses too. The next layer's anchor follows.
                skipper_.query(frame, depth_[cur].id(), {RemainingSide::NotNearerThanR});
                anchorPass(frame, cur, (layer + 1) % 3, (layer + 1) % 2, stats);
            };
            loop.run(options, [&](int layer) {
                const int cur = layer % 3, previous = (layer + 2) % 3;
                band(frame, cur, stats);
                const LayerCounts c = capture(frame, layer, previous, cur, stats);
                const std::uint64_t anchors = resolve(frame, layer % 2, c.inLayer > 0, stats);
                composited = true;
                return PeelStep{anchors + c.inLayer, anchors + c.stored, c.overflow};
            });
        }
        if (composited) composite(frame, stats);
        storage_.endFrame();
        loop.finish();
        // Four depth buffers (3 anchors, 1 band edge; 4 B each), two anchors (RGBA32UI, 16 B each), the accumulation
        // (RGBA16F, 8 B, or RGBA32F, 16 B; twice with coloured filters), the layer storage and the total counter.
        const std::uint64_t pixels = std::uint64_t(frame.size.x) * std::uint64_t(frame.size.y);
        stats.bytes = pixels * (4 * 4 + 2 * 16 + (rgb() ? 2 : 1) * floatTexelBytes(s.precision, 4)) +
                      storage_.bytes() + sizeof(GLuint);
    }

private:
    bool rgb() const { return model_ == ColorModel::RgbTransmittance; }

    void ensurePrograms(ColorModel model) {
        Programs& p = programs_.use(model);
        if (p.depth.program) return;
        p.depth = buildSceneProgram("oit/peeling/next_layer.frag.glsl", withColorModel({}, model));
        p.capture = buildSceneProgram("oit/peeling/layer_capture.frag.glsl", withColorModel(storage_.defines(), model));
        p.anchor = buildSceneProgram("oit/peeling/layer_peel.frag.glsl", withColorModel({}, model));
        p.band = gl::buildProgram({"common/fullscreen.vert.glsl", "oit/peeling/layer_band.frag.glsl"});
        gl::Defines anchored = withColorModel(storage_.defines(), model);
        anchored["ANCHOR"] = "";
        p.resolve = gl::buildProgram({"common/fullscreen.vert.glsl", "oit/peeling/layer_resolve.frag.glsl"}, anchored);
        // Where a layer's capture stored nothing anywhere (no coplanarity): the anchors alone.
        anchored["ANCHORS_ONLY"] = "";
        p.resolveAnchors = gl::buildProgram({"common/fullscreen.vert.glsl", "oit/peeling/layer_resolve.frag.glsl"}, anchored);
        p.composite = buildFullscreenProgram("oit/peeling/peel_composite.frag.glsl", model);
        if (total_) return;
        anchors_ = gl::createQuery(GL_SAMPLES_PASSED);
        total_ = gl::Buffer::create();
        glNamedBufferStorage(total_.id(), sizeof(GLuint), nullptr, GL_DYNAMIC_STORAGE_BIT | GL_MAP_READ_BIT);
    }

    void ensureTargets(glm::ivec2 size, int precision, ColorModel model) {
        if (size == size_ && precision == precision_ && model == model_) return;
        size_ = size;
        precision_ = precision;
        model_ = model;
        accum_ = gl::createTexture2D(rgbaFloatFormat(precision), size.x, size.y);
        accumFbo_ = gl::Framebuffer::create();
        glNamedFramebufferTexture(accumFbo_.id(), GL_COLOR_ATTACHMENT0, accum_.id(), 0);
        accumPasses_ = {};
        if (rgb()) {
            accumPasses_ = gl::createTexture2D(rgbaFloatFormat(precision), size.x, size.y);
            glNamedFramebufferTexture(accumFbo_.id(), GL_COLOR_ATTACHMENT1, accumPasses_.id(), 0);
            const GLenum both[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
            glNamedFramebufferDrawBuffers(accumFbo_.id(), 2, both);
        }
        for (auto& d : depth_) d = gl::createTexture2D(GL_DEPTH_COMPONENT32F, size.x, size.y);
        for (auto& a : anchor_) a = gl::createTexture2D(GL_RGBA32UI, size.x, size.y);
        anchorFbo_ = gl::Framebuffer::create();
        bandDepth_ = gl::createTexture2D(GL_DEPTH_COMPONENT32F, size.x, size.y);
        bandFbo_ = gl::Framebuffer::create();
        glNamedFramebufferTexture(bandFbo_.id(), GL_DEPTH_ATTACHMENT, bandDepth_.id(), 0);
        glNamedFramebufferDrawBuffer(bandFbo_.id(), GL_NONE);
    }

    // Binds depth_[depth] cleared to 0 (nothing anchored) with depth writes on, and anchor_[set]
    // cleared to 0 (none).
    void bindAnchorTarget(const FrameContext& frame, int depth, int set) {
        const GLuint fbo = anchorFbo_.id();
        glNamedFramebufferTexture(fbo, GL_DEPTH_ATTACHMENT, depth_[depth].id(), 0);
        glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0, anchor_[set].id(), 0);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        setTransparentDepthState(frame);
        glDepthMask(GL_TRUE);  // clears obey the mask
        const float zeroDepth = 0.0f;
        glClearNamedFramebufferfv(fbo, GL_DEPTH, 0, &zeroDepth);
        const GLuint noIds[4] = {0, 0, 0, 0};
        glClearNamedFramebufferuiv(fbo, GL_COLOR, 0, noIds);
        glDisable(GL_BLEND);
        glBindTextureUnit(gpu::BIND_OPAQUE_DEPTH, frame.targets.depth());
    }

    // Anchors layer 0 in depth_[0]; returns the number of fragments in front of the opaque depth.
    std::uint64_t firstDepthPass(const FrameContext& frame, TechniqueStats& stats) {
        gl::ScopedPass pass(frame.timer, id_ + " depth");
        const GLuint zero = 0;
        glNamedBufferSubData(total_.id(), 0, sizeof(GLuint), &zero);
        bindAnchorTarget(frame, 0, 0);
        glBindBufferBase(GL_ATOMIC_COUNTER_BUFFER, gpu::BIND_COUNTERS, total_.id());
        skipper_.draw(frame, programs_->depth, stats);
        glDepthMask(GL_FALSE);
        ++stats.passes;
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_ATOMIC_COUNTER_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
        return gl::readUint(total_);
    }

    // The far edge of the tie band of the layer anchored in depth_[cur], into bandDepth_.
    void band(const FrameContext& frame, int cur, TechniqueStats& stats) {
        gl::ScopedPass pass(frame.timer, id_ + " band");
        glBindFramebuffer(GL_FRAMEBUFFER, bandFbo_.id());
        glBindTextureUnit(gpu::BIND_PEEL_LAYER, depth_[cur].id());
        drawFullscreenDepth(frame, programs_->band.id());
        ++stats.passes;
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    }

    // Stores the coincident fragments of the layer anchored in depth_[cur] and anchor_[set of
    // the layer]; repeated when the list pool had to grow.
    LayerCounts capture(const FrameContext& frame, int layer, int previous, int cur, TechniqueStats& stats) {
        const GLuint program = programs_->capture.id();
        glProgramUniform1i(program, glGetUniformLocation(program, "uFirstLayer"), layer == 0);
        for (;;) {
            gl::ScopedPass pass(frame.timer, id_ + " capture");
            glBindFramebuffer(GL_FRAMEBUFFER, bandFbo_.id());
            setTransparentDepthState(frame);
            glDepthFunc(GL_GEQUAL);  // at or nearer than the band's far edge
            glBindTextureUnit(gpu::BIND_OPAQUE_DEPTH, frame.targets.depth());
            glBindTextureUnit(gpu::BIND_PEEL_PREVIOUS, depth_[previous].id());
            glBindTextureUnit(gpu::BIND_PEEL_LAYER, depth_[cur].id());
            glBindTextureUnit(gpu::BIND_ANCHOR, anchor_[layer % 2].id());
            storage_.beginPass(program);
            skipper_.draw(frame, programs_->capture, stats);
            ++stats.passes;
            const LayerCounts c = storage_.endPass();
            if (!c.repeat) return c;
            ++stats.regrows;
        }
    }

    // Anchors the layer behind the one in depth_[cur]: depth into depth_[next], colour and ids
    // into anchor_[set].
    void anchorPass(const FrameContext& frame, int cur, int next, int set, TechniqueStats& stats) {
        gl::ScopedPass pass(frame.timer, id_ + " anchor");
        bindAnchorTarget(frame, next, set);
        glBindTextureUnit(gpu::BIND_PEEL_LAYER, depth_[cur].id());
        skipper_.draw(frame, programs_->anchor, stats);
        glDepthMask(GL_FALSE);
        ++stats.passes;
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    }

    // anyStored: whether the capture stored (or counted) any coincident fragment.
    std::uint64_t resolve(const FrameContext& frame, int set, bool anyStored, TechniqueStats& stats) {
        gl::ScopedPass pass(frame.timer, id_ + " resolve");
        glBindFramebuffer(GL_FRAMEBUFFER, accumFbo_.id());
        const GLuint program = anyStored ? programs_->resolve.id() : programs_->resolveAnchors.id();
        if (rgb()) {
            // The resolve reads and writes its own texel of both targets (layer_resolve.frag.glsl).
            glBindTextureUnit(gpu::BIND_PEEL_ACCUM, accum_.id());
            glBindTextureUnit(gpu::BIND_PEEL_ACCUM_FILTER, accumPasses_.id());
            glTextureBarrier();
        } else {
            glEnable(GL_BLEND);
            glBlendEquation(GL_FUNC_ADD);
            glBlendFuncSeparate(GL_DST_ALPHA, GL_ONE, GL_ZERO, GL_ONE_MINUS_SRC_ALPHA);  // under
        }
        if (anyStored) storage_.bindForResolve(program);  // ANCHORS_ONLY declares no storage
        glBindTextureUnit(gpu::BIND_ANCHOR, anchor_[set].id());
        glBeginQuery(GL_SAMPLES_PASSED, anchors_.id());
        TransparentAreaScissor scissor(frame);  // nothing was stored outside it: a no-op there
        drawFullscreen(frame, program);
        glEndQuery(GL_SAMPLES_PASSED);
        glDisable(GL_BLEND);
        ++stats.passes;
        const std::uint64_t anchors = gl::queryResult(anchors_);
        return anchors;
    }

    void composite(const FrameContext& frame, TechniqueStats& stats) {
        gl::ScopedPass pass(frame.timer, id_ + " composite");
        glBindFramebuffer(GL_FRAMEBUFFER, frame.targets.outputFramebuffer());
        glDisable(GL_BLEND);
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
        glBindTextureUnit(gpu::BIND_OPAQUE_COLOR, frame.targets.opaqueColor());
        glBindTextureUnit(gpu::BIND_PEEL_ACCUM, accum_.id());
        if (rgb()) glBindTextureUnit(gpu::BIND_PEEL_ACCUM_FILTER, accumPasses_.id());
        TransparentAreaScissor scissor(frame);  // the output holds the opaque colour elsewhere
        drawFullscreen(frame, programs_->composite.id());
        ++stats.passes;
    }

    struct Programs {
        SceneProgram depth, capture, anchor;
        gl::Program band, resolve, resolveAnchors, composite;
    };
    std::string id_;
    LayerStorage storage_;
    ProgramsPerColorModel<Programs> programs_;  // oit/color_model.hpp
    gl::Buffer total_;
    gl::Query anchors_;
    glm::ivec2 size_{0, 0};
    int precision_ = 0;
    ColorModel model_ = ColorModel::Scalar;  // the targets'
    gl::Texture accum_, depth_[3], anchor_[2], bandDepth_;
    gl::Texture accumPasses_;  // the RGB build's: what the accumulation lets through per channel
    gl::Framebuffer accumFbo_, anchorFbo_, bandFbo_;
    ObjectSkipper skipper_;
};

}  // namespace
}  // namespace strata::peeling

namespace strata {

TechniqueEntry f2bLlEntry() {
    TechniqueInfo info{"f2b-ll", "coplanarity", true, true,
                       "4D+1 (depth + D band edges + D captures + D resolves + D-1 anchor passes + composite; +1 "
                       "capture per pool regrow); Table 1: 2 per iteration, 2D",
                       "w*h*64 B at precision=32 (4 depth 4 B, 2 anchors RGBA32UI (packed colour, ids), RGBA32F "
                       "accumulation) + w*h*4 heads + 24 B per coincident fragment beside the anchors of the largest "
                       "layer (pool grown to it); + one RGBA target in a scene with coloured filters; Table 1: 2C(Z)+4 words",
                       "F2B-LL (Algorithm 2): f2b's peel under the tie rule anchors each layer; a capture pass, "
                       "depth-tested early against the layer's band, links its coincident fragments into per-pixel "
                       "lists, resolved with the anchor in object order"};
    info.rgbTransmittance = true;
    return techniqueEntry<peeling::LayerPeelingTechnique<peeling::LayerListSettings, peeling::FrontToBackLayers>>(
        info, peeling::LayerStore::List);
}

TechniqueEntry f2bFabEntry() {
    TechniqueInfo info{"f2b-fab", "coplanarity", false, true,
                       "4D+1 (depth + D band edges + D captures + D resolves + D-1 anchor passes + composite); Table 1: "
                       "2 per iteration, 2D",
                       "w*h*(64 + 20(K-1) + 4) B at precision=32 (4 depth, 2 anchors, + RGBA32F accumulation, K-1 entries + counter beside the anchor; "
                       "+ one RGBA target with coloured filters); "
                       "Table 1: K+4 words",
                       "F2B-FAB (Algorithm 3): per layer, up to K coincident fragments per pixel in a fixed array "
                       "with a per-pixel counter; R_h = sum min(K, C(Z_i)) / total, the rest counted as overflow"};
    info.rgbTransmittance = true;
    return techniqueEntry<peeling::LayerPeelingTechnique<peeling::LayerBufferSettings, peeling::FrontToBackLayers>>(
        info, peeling::LayerStore::Fab);
}

TechniqueEntry f2bKbEntry() {
    TechniqueInfo info{"f2b-kb", "coplanarity", false, true,
                       "4D+1 (depth + D band edges + D captures + D resolves + D-1 anchor passes + composite); Table 1: "
                       "2 per iteration, 2D",
                       "w*h*(64 + 20(K-1)) B at precision=32 (4 depth, 2 anchors, + RGBA32F accumulation, K-1 slots beside the anchor; + one "
                       "RGBA target with coloured filters); Table 1: K+3 "
                       "words",
                       "F2B-KB (Algorithm 3): per layer, up to K coincident fragments per pixel in k-buffer slots "
                       "claimed in order by compare-and-swap (no counter); the rest counted as overflow"};
    info.rgbTransmittance = true;
    return techniqueEntry<peeling::LayerPeelingTechnique<peeling::LayerBufferSettings, peeling::FrontToBackLayers>>(
        info, peeling::LayerStore::KBuffer);
}

}  // namespace strata
