#pragma once
// One frame, start to end: opaque pass into colour and depth, then the transparency technique
// composites over it into the output colour. A scene with nothing transparent gets no
// transparency pass at all. Optionally counts every transparent fragment in front of the opaque
// depth once, by one shared method, so every technique's robustness ratio means the same.
//
// Layering: render/ (GL scene resources, targets, programs, depth order) <- oit/ (techniques,
// which use render/) <- frame/ (this, which runs a technique). Nothing below includes upward.
#include "camera/camera.hpp"
#include "gl/gpu_timer.hpp"
#include "image/image.hpp"
#include "oit/coplanarity_detector.hpp"
#include "oit/technique.hpp"
#include "render/deflection_warp.hpp"
#include "render/frame_targets.hpp"
#include "render/gpu_scene.hpp"

#include <memory>
#include <optional>

namespace strata {

struct FrameOptions {
    bool timePasses = true;
    bool countFragments = false;
    bool reverseSubmission = false;   // draw transparent objects in the reverse of the technique's order
    // Run the coplanarity detector (oit/coplanarity_detector.hpp) after the technique: its
    // heatmap and counts are then in coplanarity(), its figures in FrameResult::coplanarity.
    bool detectCoplanarity = false;
    double coplanarityMaxBlockMiB = 0.0;  // > 0 caps the detector's node pool (tests force tiles)
    // Zoom rendering (render/zoom.hpp): the frame is drawn at zoomRenderSize(size, zoom), every
    // technique's buffers sized to that, then enlarged to `size` in one pass (timed as "enlarge")
    // by pixel replication (`nearest`) or with a blur (`bilinear`). At 1 nothing is copied.
    int zoom = 1;
    DeflectFilter zoomFilter = DeflectFilter::Nearest;
    // false: keep the reduced frame (targets()) and enlarge nothing; the caller folds the
    // enlargement into its own pass (immersive mode's deflection: DeflectionParams::zoom).
    bool enlarge = true;
    // What draws in objects' places (layered impostors, lod/), indexed like GpuScene::objects();
    // null entries and a null pointer draw the objects' triangles. Held by the caller.
    const StandIns* standIns = nullptr;
    // Objects whose bounding sphere lies outside the view frustum are drawn by no pass
    // (render/frustum.hpp); false draws every object (the coplanarity detector's counts and
    // the images are the same either way: a culled object has no fragment in the view).
    bool cull = true;
};

struct FrameResult {
    std::vector<gl::PassTime> passTimes;
    double gpuMs = 0.0;     // sum over passes, the coplanarity detector's apart
    // From the first pass's start to the last pass's end on the GPU clock, the detector's passes
    // left out: the frame's GPU time with idle gaps between passes in and overlaps counted once.
    double gpuSpanMs = 0.0;
    double coplanarityMs = 0.0;  // GPU time of the detector's passes (in passTimes too)
    double cpuMs = 0.0;     // wall time of the whole frame, including waits for results
    // CPU time of the thread that rendered the frame (its own, not the driver's worker threads;
    // a software driver such as llvmpipe shades vertices on it too), and the GL draws of scene
    // objects its passes issued (GpuScene::drawCalls): what submission costs per object.
    double threadCpuMs = 0.0;
    std::uint64_t drawCalls = 0;
    TechniqueStats stats;
    std::optional<std::uint64_t> fragmentsTotal;
    std::optional<CoplanarityStats> coplanarity;  // when FrameOptions::detectCoplanarity
    bool transparencyPass = false;
    int zoom = 1;
    glm::ivec2 renderSize{0, 0};   // what was drawn: zoomRenderSize(size, zoom)
    double enlargeMs = 0.0;        // GPU time of the enlargement (in gpuMs and passTimes too)
    std::size_t objectsCulled = 0; // outside the view frustum: drawn by no pass this frame
    // LOD unit instances (Object::unit) whose parts' geometry the culling hierarchy found wholly
    // outside (render/cull_hierarchy.hpp). A unit drawn as a stand-in is culled by the stand-in's
    // own bounds, which reach a little further, so it may still be drawn.
    std::size_t unitsCulled = 0;
};

class FrameRenderer {
public:
    FrameResult render(const GpuScene& scene, const Camera& camera, glm::ivec2 size, Technique* technique,
                       const FrameOptions& options = {});
    // The last frame's output colour (linear RGB, alpha 1) at the size asked for, bottom row first:
    // the enlarged frame when it was zoomed, the targets' output otherwise.
    Image readOutput() const;
    GLuint outputColor() const { return enlarged_ ? enlarge_.outputColor() : targets_.outputColor(); }
    // The targets the frame was drawn into (the reduced frame when zoomed).
    const FrameTargets& targets() const { return targets_; }
    // The detector of the last frame that asked for one (null before any did).
    const CoplanarityDetector* coplanarity() const { return detector_.get(); }

private:
    std::uint64_t countFragments(const FrameContext& frame);

    FrameTargets targets_;
    std::vector<int> opaqueOrder_;  // the frame's opaque objects left after culling
    std::vector<char> visible_;     // per object: the culling hierarchy's answer this frame
    gl::GpuTimer timer_;
    SceneProgram opaqueProgram_, countProgram_;
    gl::Buffer counter_;
    std::unique_ptr<CoplanarityDetector> detector_;  // created on the first frame that detects
    DeflectionWarp enlarge_;  // zoom's enlargement: the identity map at the frame's zoom
    bool enlarged_ = false;   // the last frame's output is enlarge_'s
};

}  // namespace strata
