// `f2b-ll`, `f2b-fab`, `f2b-kb`: front-to-back peeling that captures every coincident fragment
// of a layer (depth-fighting paper, Algorithm 2 F2B-LL and Algorithm 3 F2B-B). Per iteration:
//   1. depth pass (geometry, depth only): the nearest fragment not yet peeled anchors the layer;
//   2. capture pass (geometry, early depth test against the opaque depth): every fragment not
//      yet peeled within the tie tolerance of that depth (layer_tie.glsl, the project's tie rule,
//      not bit-equal depths) goes into per-pixel storage (layer_storage.hpp): linked lists whose
//      pool grows to the layer (f2b-ll, robust), or K entries per pixel (f2b-fab, f2b-kb:
//      bounded, the rest of the layer is counted as overflow);
//   3. resolve (full screen): the layer's fragments in object, then primitive order (the exact
//      order of ordered_composite.glsl), blended under the accumulation.
// Then one composite over the opaque colour. The first depth pass counts every fragment; each
// capture counts the layer's fragments (stored or not), so the loop ends on the layer that
// leaves nothing, after exactly as many iterations as there are layers.
#include "oit/technique.hpp"

#include "common/bindings.h"
#include "oit/draw_transparent.hpp"
#include "oit/peeling/layer_settings.hpp"
#include "oit/peeling/layer_storage.hpp"
#include "oit/peeling/object_skipper.hpp"
#include "oit/peeling/peel_bindings.h"
#include "oit/precision.hpp"

namespace strata::peeling {
namespace {

class FrontToBackLayers {
public:
    FrontToBackLayers(const std::string& id, LayerStore kind) : id_(id), storage_(kind, id) {}

    void render(const FrameContext& frame, const LayerPeelingSettings& s, TechniqueStats& stats) {
        ensurePrograms();
        ensureTargets(frame.size, s.precision);
        stats = {};
        skipper_.beginFrame(frame, s.skipPeeled);
        storage_.prepare(frame.size, 1, s.capacity, s.maxBlockMiB);
        const float clearAccum[4] = {0, 0, 0, 1};
        glClearTexImage(accum_.id(), 0, GL_RGBA, GL_FLOAT, clearAccum);
        setDepthOrderUniforms(frame, depthProgram_.id());
        setDepthOrderUniforms(frame, captureProgram_.id());
        setDepthOrderUniforms(frame, resolveProgram_.id());

        std::uint64_t total = 0, remaining = 0, overflow = 0;
        bool composited = false;
        for (int layer = 0;; ++layer) {
            if (layer >= s.maxPasses) {
                stats.overflowed = true;
                break;
            }
            const int cur = layer % 2;
            const bool anyLeft = depthPass(frame, layer, cur, stats);
            if (layer == 0) total = remaining = readTotal();
            if (remaining == 0 || !anyLeft) break;
            const LayerCounts c = capture(frame, layer, cur, stats);
            if (c.inLayer == 0) break;  // a guard: a depth pass that found a layer captures it
            resolve(frame, stats);
            composited = true;
            stats.fragmentsCaptured += c.stored;
            overflow += c.overflow;
            if (c.inLayer >= remaining) break;
            remaining -= c.inLayer;
            skipper_.query(frame, depth_[cur].id(), {RemainingSide::NotNearerThanR});
        }
        if (composited) composite(frame, stats);
        skipper_.endFrame(stats);
        storage_.endFrame();
        stats.fragmentsDropped = total > stats.fragmentsCaptured ? total - stats.fragmentsCaptured : 0;
        if (overflow > 0) stats.overflowed = true;
        // Two depth buffers (4 B each), the accumulation (RGBA16F, 8 B, or RGBA32F, 16 B), the
        // layer storage and the total counter.
        const std::uint64_t pixels = std::uint64_t(frame.size.x) * std::uint64_t(frame.size.y);
        stats.bytes = pixels * (2 * 4 + floatTexelBytes(s.precision, 4)) + storage_.bytes() + sizeof(GLuint);
    }

private:
    void ensurePrograms() {
        if (depthProgram_.program) return;
        depthProgram_ = buildSceneProgram("oit/peeling/next_layer.frag.glsl");
        captureProgram_ = buildSceneProgram("oit/peeling/layer_capture.frag.glsl", storage_.defines());
        resolveProgram_ =
            gl::buildProgram({"common/fullscreen.vert.glsl", "oit/peeling/layer_resolve.frag.glsl"}, storage_.defines());
        compositeProgram_ = gl::buildProgram({"common/fullscreen.vert.glsl", "oit/peeling/peel_composite.frag.glsl"});
        total_ = gl::Buffer::create();
        glNamedBufferStorage(total_.id(), sizeof(GLuint), nullptr, GL_DYNAMIC_STORAGE_BIT | GL_MAP_READ_BIT);
        anyLeft_ = gl::createQuery(GL_ANY_SAMPLES_PASSED);
    }

    void ensureTargets(glm::ivec2 size, int precision) {
        if (size == size_ && precision == precision_) return;
        size_ = size;
        precision_ = precision;
        accum_ = gl::createTexture2D(rgbaFloatFormat(precision), size.x, size.y);
        accumFbo_ = gl::Framebuffer::create();
        glNamedFramebufferTexture(accumFbo_.id(), GL_COLOR_ATTACHMENT0, accum_.id(), 0);
        for (int i = 0; i < 2; ++i) {
            depth_[i] = gl::createTexture2D(GL_DEPTH_COMPONENT32F, size.x, size.y);
            depthFbo_[i] = gl::Framebuffer::create();
            glNamedFramebufferTexture(depthFbo_[i].id(), GL_DEPTH_ATTACHMENT, depth_[i].id(), 0);
            glNamedFramebufferDrawBuffer(depthFbo_[i].id(), GL_NONE);
        }
    }

    // The nearest fragment the previous layer (depth_[1 - cur]) did not peel, into depth_[cur];
    // returns whether there was any (exact whatever the order: the first such fragment at a
    // pixel passes against the cleared buffer). The first pass counts every fragment.
    bool depthPass(const FrameContext& frame, int layer, int cur, TechniqueStats& stats) {
        gl::ScopedPass pass(frame.timer, id_ + " depth");
        if (layer == 0) {
            const GLuint zero = 0;
            glNamedBufferSubData(total_.id(), 0, sizeof(GLuint), &zero);
        }
        glBindFramebuffer(GL_FRAMEBUFFER, depthFbo_[cur].id());
        setTransparentDepthState(frame);
        glDepthMask(GL_TRUE);  // clears obey the mask
        const float zeroDepth = 0.0f;
        glClearNamedFramebufferfv(depthFbo_[cur].id(), GL_DEPTH, 0, &zeroDepth);
        glDisable(GL_BLEND);
        glBindTextureUnit(gpu::BIND_OPAQUE_DEPTH, frame.targets.depth());
        glBindTextureUnit(gpu::BIND_PEEL_PREVIOUS, depth_[1 - cur].id());
        glBindBufferBase(GL_ATOMIC_COUNTER_BUFFER, gpu::BIND_COUNTERS, total_.id());
        glProgramUniform1i(depthProgram_.id(), glGetUniformLocation(depthProgram_.id(), "uFirstLayer"), layer == 0);
        glBeginQuery(GL_ANY_SAMPLES_PASSED, anyLeft_.id());
        skipper_.draw(frame, depthProgram_, stats);
        glEndQuery(GL_ANY_SAMPLES_PASSED);
        glDepthMask(GL_FALSE);
        ++stats.passes;
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
        GLuint any = 0;
        glGetQueryObjectuiv(anyLeft_.id(), GL_QUERY_RESULT, &any);
        return any != 0;
    }

    std::uint64_t readTotal() {
        glMemoryBarrier(GL_ATOMIC_COUNTER_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
        return gl::readUint(total_);
    }

    // Stores the layer anchored in depth_[cur]; repeated when the list pool had to grow.
    LayerCounts capture(const FrameContext& frame, int layer, int cur, TechniqueStats& stats) {
        const GLuint program = captureProgram_.id();
        glProgramUniform1i(program, glGetUniformLocation(program, "uFirstLayer"), layer == 0);
        for (;;) {
            gl::ScopedPass pass(frame.timer, id_ + " capture");
            glBindFramebuffer(GL_FRAMEBUFFER, frame.targets.outputFramebuffer());
            setTransparentDepthState(frame);
            glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
            glBindTextureUnit(gpu::BIND_PEEL_PREVIOUS, depth_[1 - cur].id());
            glBindTextureUnit(gpu::BIND_PEEL_LAYER, depth_[cur].id());
            storage_.beginPass(program);
            skipper_.draw(frame, captureProgram_, stats);
            glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
            ++stats.passes;
            const LayerCounts c = storage_.endPass();
            if (!c.repeat) return c;
            ++stats.regrows;
        }
    }

    void resolve(const FrameContext& frame, TechniqueStats& stats) {
        gl::ScopedPass pass(frame.timer, id_ + " resolve");
        glBindFramebuffer(GL_FRAMEBUFFER, accumFbo_.id());
        glEnable(GL_BLEND);
        glBlendEquation(GL_FUNC_ADD);
        glBlendFuncSeparate(GL_DST_ALPHA, GL_ONE, GL_ZERO, GL_ONE_MINUS_SRC_ALPHA);  // under
        storage_.bindForResolve(resolveProgram_.id());
        drawFullscreen(frame, resolveProgram_.id());
        glDisable(GL_BLEND);
        ++stats.passes;
    }

    void composite(const FrameContext& frame, TechniqueStats& stats) {
        gl::ScopedPass pass(frame.timer, id_ + " composite");
        glBindFramebuffer(GL_FRAMEBUFFER, frame.targets.outputFramebuffer());
        glDisable(GL_BLEND);
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
        glBindTextureUnit(gpu::BIND_OPAQUE_COLOR, frame.targets.opaqueColor());
        glBindTextureUnit(gpu::BIND_PEEL_ACCUM, accum_.id());
        drawFullscreen(frame, compositeProgram_.id());
        ++stats.passes;
    }

    std::string id_;
    LayerStorage storage_;
    SceneProgram depthProgram_, captureProgram_;
    gl::Program resolveProgram_, compositeProgram_;
    gl::Buffer total_;
    gl::Query anyLeft_;
    glm::ivec2 size_{0, 0};
    int precision_ = 0;
    gl::Texture accum_, depth_[2];
    gl::Framebuffer accumFbo_, depthFbo_[2];
    ObjectSkipper skipper_;
};

}  // namespace
}  // namespace strata::peeling

namespace strata {

TechniqueEntry f2bLlEntry() {
    TechniqueInfo info{"f2b-ll", "coplanarity", true, true,
                       "3D+1 (D depth passes + D captures + D resolves + composite; +1 capture per pool regrow); "
                       "Table 1: 2 per iteration, 2D",
                       "w*h*24 B at precision=32 (2 depth 4 B + RGBA32F accumulation) + w*h*4 heads + 24 B per "
                       "fragment of the largest layer (pool grown to it); Table 1: 2C(Z)+4 words",
                       "F2B-LL (Algorithm 2): depth pass finds the next layer, a capture pass links every fragment "
                       "within the tie tolerance of it into per-pixel lists, resolved in object order"};
    return techniqueEntry<peeling::LayerPeelingTechnique<peeling::LayerListSettings, peeling::FrontToBackLayers>>(
        info, peeling::LayerStore::List);
}

TechniqueEntry f2bFabEntry() {
    TechniqueInfo info{"f2b-fab", "coplanarity", false, true,
                       "3D+1 (D depth passes + D captures + D resolves + composite); Table 1: 2 per iteration, 2D",
                       "w*h*(24 + 20K + 4) B at precision=32 (2 depth + RGBA32F accumulation, K entries + counter); "
                       "Table 1: K+4 words",
                       "F2B-FAB (Algorithm 3): per layer, up to K coincident fragments per pixel in a fixed array "
                       "with a per-pixel counter; R_h = sum min(K, C(Z_i)) / total, the rest counted as overflow"};
    return techniqueEntry<peeling::LayerPeelingTechnique<peeling::LayerBufferSettings, peeling::FrontToBackLayers>>(
        info, peeling::LayerStore::Fab);
}

TechniqueEntry f2bKbEntry() {
    TechniqueInfo info{"f2b-kb", "coplanarity", false, true,
                       "3D+1 (D depth passes + D captures + D resolves + composite); Table 1: 2 per iteration, 2D",
                       "w*h*(24 + 20K) B at precision=32 (2 depth + RGBA32F accumulation, K slots); Table 1: K+3 "
                       "words",
                       "F2B-KB (Algorithm 3): per layer, up to K coincident fragments per pixel in k-buffer slots "
                       "claimed in order by compare-and-swap (no counter); the rest counted as overflow"};
    return techniqueEntry<peeling::LayerPeelingTechnique<peeling::LayerBufferSettings, peeling::FrontToBackLayers>>(
        info, peeling::LayerStore::KBuffer);
}

}  // namespace strata
