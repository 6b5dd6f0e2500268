#include "frame/frame_renderer.hpp"

#include "render/batch_order.hpp"
#include "render/frustum.hpp"
#include "render/texture_readback.hpp"
#include "render/zoom.hpp"

#include "common/bindings.h"
#include "gl/debug.hpp"
#include "oit/draw_transparent.hpp"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <limits>

namespace strata {
namespace {

// CPU time the calling thread has used, in ms.
double threadCpuMs() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

// STRATA_DEBUG_UNBIND_AFTER_FRAME=1: no program or vertex array stays bound after a frame (so a
// renderer or technique deleted after it never deletes a bound one): a GPU diagnostic.
bool unbindAfterFrame() {
    static const bool on = gl::debugSwitch("STRATA_DEBUG_UNBIND_AFTER_FRAME");
    return on;
}

}  // namespace

FrameResult FrameRenderer::render(const GpuScene& scene, const Camera& camera, glm::ivec2 size,
                                  Technique* technique, const FrameOptions& options) {
    auto cpuStart = std::chrono::steady_clock::now();
    const double threadStart = threadCpuMs();
    const std::uint64_t drawsBefore = scene.drawCalls();
    const glm::ivec2 displaySize = size;
    size = zoomRenderSize(displaySize, options.zoom);
    targets_.resize(size);
    enlarged_ = false;
    if (!opaqueProgram_.program) opaqueProgram_ = buildSceneProgram("common/opaque.frag.glsl");
    gl::GpuTimer* timer = options.timePasses ? &timer_ : nullptr;

    glm::mat4 view = camera.view();
    glm::mat4 projection =
        zoomProjection(camera.projection(float(displaySize.x) / float(displaySize.y)), displaySize, options.zoom);
    const bool ordered = technique && technique->info().keepsSubmissionOrder;
    FrameContext frame{scene, camera, view, projection, projection * view, size, targets_, timer,
                       ordered ? scene.transparentObjects() : scene.transparentObjectsBatched(), options.standIns};
    // Only what can reach the view is drawn, by the opaque pass and by every technique's passes
    // (they draw frame.transparentOrder).
    // Batched: the depth test decides, and where two opaque surfaces tie in depth no order is right.
    opaqueOrder_ = scene.opaqueObjectsBatched();
    // A LOD unit's other parts stay in the orders though their stand-in draws nothing: a
    // technique that samples meshes rather than drawing (screendoor-object-sw) still needs them.
    std::size_t culled = 0, unitsCulled = 0;
    if (options.cull) {
        // The hierarchy answers for every object (render/cull_hierarchy.hpp); a LOD unit's stand-in
        // is tested by its own bounds, which hold all the unit's parts.
        const Frustum frustum(frame.viewProjection);
        const CullCounts counts = scene.cullHierarchy().cull(frustum, visible_);
        unitsCulled = counts.unitsCulled;
        auto outside = [&](int object) {
            const StandInDraw* s = frame.standInOf(object);
            if (s && !s->worldBounds.empty()) return !frustum.mayContain(s->worldBounds);
            return !visible_[std::size_t(object)];
        };
        for (std::vector<int>* order : {&opaqueOrder_, &frame.transparentOrder}) {
            const auto kept = std::remove_if(order->begin(), order->end(), outside);
            culled += std::size_t(order->end() - kept);
            order->erase(kept, order->end());
        }
    }
    // Batches nearest first (render/batch_order.hpp), except where submission order is the image.
    const glm::vec3 eye = camera.position, forward = camera.forward();
    auto nearest = [&](int o) {
        const Bounds& b = frame.boundsOf(o);
        if (b.empty()) return std::numeric_limits<float>::max();
        return glm::dot(b.center() - eye, forward) - glm::dot(glm::abs(forward), 0.5f * (b.max - b.min));
    };
    auto sameRun = [&](int a, int b) {
        const StandInDraw *sa = frame.standInOf(a), *sb = frame.standInOf(b);
        if (!sa && !sb) return scene.sameBatch(a, b);
        return sa && sb && scene.sameStandInBatch(a, *sa, b, *sb);
    };
    // Within a batch, the stand-ins that one instanced draw can take next to each other (the
    // same impostor seen from the same view direction): geometry first, then stand-ins by draw.
    // The orders come grouped by mesh and material, so only the groups holding stand-ins sort.
    auto groupStandIns = [&](std::vector<int>& order) {
        if (!frame.standIns) return;
        const auto& objects = scene.objects();
        auto sameGroup = [&](int a, int b) {
            const Object &x = objects[std::size_t(a)], &y = objects[std::size_t(b)];
            return x.mesh == y.mesh && x.material == y.material;
        };
        auto byDraw = [&](int a, int b) {
            const StandInDraw *sa = frame.standInOf(a), *sb = frame.standInOf(b);
            if (!sa || !sb) return !sa && sb;
            return standInDrawBefore(*sa, *sb);
        };
        for (auto begin = order.begin(); begin != order.end();) {
            auto end = std::find_if_not(begin + 1, order.end(), [&](int o) { return sameGroup(*begin, o); });
            if (std::count_if(begin, end, [&](int o) { return frame.standInOf(o) != nullptr; }) > 1)
                std::stable_sort(begin, end, byDraw);
            begin = end;
        }
    };
    groupStandIns(opaqueOrder_);
    orderRunsNearestFirst(opaqueOrder_, sameRun, nearest);
    if (!ordered) {
        groupStandIns(frame.transparentOrder);
        orderRunsNearestFirst(frame.transparentOrder, sameRun, nearest);
    }
    if (options.reverseSubmission) std::reverse(frame.transparentOrder.begin(), frame.transparentOrder.end());
    // Where the transparent objects can draw: the full-screen passes that only act there scissor to it.
    PixelRect area;
    for (int o : frame.transparentOrder) {
        area = area.unite(pixelsReached(frame.viewProjection, frame.boundsOf(o), size));
        if (area.size == size) break;  // the whole frame
    }
    frame.transparentArea = area;

    glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    glBindFramebuffer(GL_FRAMEBUFFER, targets_.opaqueFramebuffer());
    {
        gl::ScopedPass pass(timer, "opaque");
        glViewport(0, 0, size.x, size.y);
        glDisable(GL_SCISSOR_TEST);
        glDisable(GL_BLEND);
        glDisable(GL_CULL_FACE);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_GREATER);
        glDepthMask(GL_TRUE);
        const glm::vec3 bg = scene.scene().background;
        const float clearColor[4] = {bg.r, bg.g, bg.b, 1.0f};
        const float clearDepth = 0.0f;  // reversed-Z: 0 is the far plane
        glClearNamedFramebufferfv(targets_.opaqueFramebuffer(), GL_COLOR, 0, clearColor);
        glClearNamedFramebufferfv(targets_.opaqueFramebuffer(), GL_DEPTH, 0, &clearDepth);
        glUseProgram(opaqueProgram_.id());
        scene.setFrameUniforms(opaqueProgram_, frame.viewProjection);
        frame.drawAll(opaqueProgram_, opaqueOrder_);
    }
    targets_.copyOpaqueToOutput();

    FrameResult result;
    result.objectsCulled = culled;
    result.unitsCulled = unitsCulled;
    // A view whose transparent objects are all culled has no transparent fragment: no pass.
    if (technique && !frame.transparentOrder.empty()) {
        technique->render(frame);
        result.stats = technique->stats();
        result.transparencyPass = true;
    }
    if (options.countFragments) result.fragmentsTotal = scene.hasTransparency() ? countFragments(frame) : 0;
    if (options.detectCoplanarity) {
        // Also without transparency: the heatmap is then all grey, and the viewer shows that.
        if (!detector_ || detector_->maxBlockMiB() != options.coplanarityMaxBlockMiB)
            detector_ = std::make_unique<CoplanarityDetector>(options.coplanarityMaxBlockMiB);
        result.coplanarity = detector_->detect(frame);
    }
    if (options.zoom > 1 && options.enlarge) {
        gl::ScopedPass pass(timer, "enlarge");
        DeflectionParams identity;
        identity.zoom = options.zoom;
        identity.filter = options.zoomFilter;
        enlarge_.apply(targets_.outputColor(), displaySize, identity);
        enlarged_ = true;
    }
    result.zoom = options.zoom;
    result.renderSize = size;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (unbindAfterFrame()) {
        glUseProgram(0);
        glBindVertexArray(0);
    }
    if (timer) result.passTimes = timer_.resolve();
    glFinish();
    GLuint64 first = ~GLuint64(0), last = 0;
    for (const auto& p : result.passTimes) {
        // The detector is an inspection tool, not part of the technique's cost.
        if (p.name.rfind(CoplanarityDetector::kPassPrefix, 0) == 0) {
            result.coplanarityMs += p.gpuMs;
            continue;
        }
        result.gpuMs += p.gpuMs;
        if (p.name == "enlarge") result.enlargeMs += p.gpuMs;
        if (p.endNs > p.beginNs) {
            first = std::min(first, p.beginNs);
            last = std::max(last, p.endNs);
        }
    }
    // The detector runs between the technique and the enlargement: its time is not the frame's.
    if (last > first) result.gpuSpanMs = std::max(0.0, double(last - first) * 1e-6 - result.coplanarityMs);
    result.cpuMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - cpuStart).count();
    result.threadCpuMs = threadCpuMs() - threadStart;
    result.drawCalls = scene.drawCalls() - drawsBefore;
    return result;
}

std::uint64_t FrameRenderer::countFragments(const FrameContext& frame) {
    if (!countProgram_.program) {
        countProgram_ = buildSceneProgram("common/count_fragments.frag.glsl");
        counter_ = gl::Buffer::create();
        glNamedBufferStorage(counter_.id(), sizeof(GLuint), nullptr, GL_DYNAMIC_STORAGE_BIT);
    }
    GLuint zero = 0;
    glNamedBufferSubData(counter_.id(), 0, sizeof(GLuint), &zero);
    // A scratch pass: draws into the output framebuffer with colour writes off.
    glBindFramebuffer(GL_FRAMEBUFFER, targets_.outputFramebuffer());
    setTransparentDepthState(frame);
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glBindBufferBase(GL_ATOMIC_COUNTER_BUFFER, gpu::BIND_COUNTERS, counter_.id());
    drawTransparent(frame, countProgram_, frame.transparentOrder);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glMemoryBarrier(GL_ATOMIC_COUNTER_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    return gl::readUint(counter_);
}

Image FrameRenderer::readOutput() const {
    return enlarged_ ? enlarge_.readOutput() : readRgbaTexture(targets_.outputColor(), targets_.size());
}

}  // namespace strata
