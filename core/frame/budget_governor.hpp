#pragma once
// One frame budget for two levers (issue 24): the zoom factor (zoom rendering, Mazuryk et al.
// 1996, section 3: "choose zoom factor based on graphics load, LOD algorithm, head movement
// speed") and the LOD error bound (the layered-impostor paper's cost model decides, per object,
// whether its impostor is cheaper; a larger bound lets more objects be impostors). CPU only: the
// renderer measures and the LOD controller previews, this decides.
//
// The rule: among the (zoom, bound) states predicted to fit the target, the one that loses the
// least; when none fits, the one predicted fastest. Loss is one unit for both levers: the mean
// screen-space error per display pixel, in display pixels,
//  - zoom z: every covered pixel shows a sample up to zoomLossPx(z) away (the enlarged block's
//    corner from its sample), over the share of the display objects cover;
//  - LOD at bound b: each impostor's error bound (parallax + sampling, lod/lod_error.hpp) over
//    its screen area (LodLevelPreview::lossPx, from the LOD controller);
// each times a per-lever scale (LossScales) that calibration may measure as image RMSE per pixel
// of error (1 and 1 leave the pixel units as they are).
//  - predictive: the time of every state, before the frame, from the zoom cost model (pixels,
//    fragments) plus the LOD selection's predicted time at each bound (its pixel part divided by
//    z^2, the impostors' quad sides by z), and two corrections learnt from the frames drawn: an
//    offset (what both models miss, a constant bias of LOD's included) and a factor on LOD's
//    pixel and side parts (least squares over the last frames, once they spread it: two zooms,
//    or a view that changed it). A bias that grows with the bound is not learnt.
//  - reactive: from the measured median of the last `holdFrames` frames at the current state:
//    over budget it moves to a lossier state (more zoom, a larger bound, or both), under it to a
//    less lossy one, and never within the band. Each state is estimated as the measured time
//    plus the models' difference between the two states: the zoom model's pixels and fragments
//    and LOD's selection (its pixel and side parts times a factor learnt from each change of
//    zoom alone); the rest of the frame is taken as fixed. Without a calibrated zoom model (the
//    tests' devices may have none), a share of the time scales with the pixels instead: learnt
//    from a change of zoom alone, and before one, all but LOD's preview of its geometry. A frame
//    over twice the target is judged at once instead of after the hold, and two frames in a row
//    over the band on their median. Relief (under the band) waits the hold and eases each lever
//    by one step at most. The frames were measured at their own views: the decision is taken in
//    choose(), for the coming view, with the measured time moved by the difference of LOD's
//    preview of the current state between that view and the frames' views. A growth the
//    preview sees wider than the band, taking the state over it, acts before the hold ends (on
//    the field's sweep the load rose 2-3x in six frames, and two frames over the band were
//    drawn before each step).
// With the zoom lever alone it is today's zoom controller (frame/zoom_controller.hpp), unchanged.
#include "frame/zoom_controller.hpp"

#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace strata {

struct BudgetLevers {
    bool zoom = true;
    bool lod = true;
};
// "zoom", "lod", "zoom,lod" (either order); anything else throws std::invalid_argument naming
// the known ones.
BudgetLevers parseBudgetLevers(std::string_view text);
std::string to_string(BudgetLevers levers);

// The LOD error bounds the governor chooses among: basePx x 2^k for k = 0 .. levels - 1.
struct LodLadder {
    double basePx = 4.0;
    int levels = 4;
    double bound(int level) const;
    std::vector<double> bounds() const;
};

// What LOD would do this frame at one error bound (LodController::previewBounds).
struct LodLevelPreview {
    double boundPx = 0.0;
    double predictedMs = 0.0;  // the selection's predicted time at zoom 1 (LodSelection::predictedMs)
    double pixelMs = 0.0;      // the part of it that scales with the frame's pixels (1 / z^2 at zoom z)
    // The impostors' error bounds weighted by their screen discs, over the larger of the discs'
    // summed area and the display's: a mean error in display pixels, at most the bound.
    double lossPx = 0.0;
    int impostorObjects = 0;
    // The part that scales with the impostors' quad sides (1 / z at zoom z: as many quads, each
    // side z times shorter; lod/lod_cost_model.hpp).
    double sideMs = 0.0;
};

struct LodPreview {
    std::vector<LodLevelPreview> levels;  // one per ladder level; empty: no LOD lever this frame
    double coverage = 1.0;                // share of the display the objects' discs cover (0..1)
};

struct GovernorLoad {
    FrameLoad zoom;   // display size, transparent area, the head-speed floor
    LodPreview lod;
};

struct GovernorChoice {
    int zoom = 1;
    int lodLevel = 0;         // index into the ladder (0 without the LOD lever)
    double predictedMs = 0.0; // NaN where the policy has no estimate yet
    double lossPx = 0.0;      // the state's loss under the rule above
};

// Per-lever weights of the loss (image RMSE per pixel of error, or 1 for pixel units).
struct LossScales {
    double zoom = 1.0;
    double lod = 1.0;
};

// Reactive without a calibrated zoom model, before a change of zoom alone has measured it: the
// share of the frame time at zoom 1 that scales with pixels, from a frame of `ms` drawn at a zoom
// whose pixels are `pixelRatio` of zoom 1's, of which `fixedMs` (LOD's preview: its predicted
// time less its pixel and quad-side parts) is taken as the only part no zoom shrinks. In
// [0.02, 1]; 1 where nothing is known.
double priorPixelShare(double ms, double fixedMs, double pixelRatio);

// Whether a governor of this kind and levers needs the zoom cost calibrated on the device
// (frame/zoom_calibration.hpp) before its first frame: the predictive policy always; the
// reactive one with both levers, whose estimates of the states are the models' differences.
// The zoom lever alone under the reactive policy is today's zoom controller, which needs none.
bool budgetNeedsCalibration(ZoomControllerKind kind, BudgetLevers levers);

// The farthest a display pixel lies from the sample it shows when a zoom-z frame is enlarged by
// replication: a block corner from the block's sample, (z - 1) / 2 along each axis.
double zoomLossPx(int zoom);

class BudgetGovernor {
public:
    BudgetGovernor(const ZoomBudget& budget, BudgetLevers levers, ZoomControllerKind kind, const ZoomCostModel& model,
                   LossScales scales = {});
    // The state for the next frame. The caller draws with it and reports it through observe.
    GovernorChoice choose(const GovernorLoad& load);
    // The frame just drawn with the last choice (cost.zoom must be the chosen zoom).
    void observe(const FrameCost& cost);

    const ZoomBudget& budget() const { return budget_; }
    BudgetLevers levers() const { return levers_; }
    ZoomControllerKind kind() const { return kind_; }
    const ZoomCostModel& model() const { return model_; }
    const GovernorChoice& last() const { return last_; }
    // The state's loss for a load (the rule's; public for tests and the panel).
    double loss(const GovernorLoad& load, int zoom, int level) const;
    // The factor on LOD's predicted pixel and side parts learnt from the frames drawn (1 until
    // they spread it; reactive: until a change of zoom alone, with a calibrated zoom model). The
    // LOD cost model's rates come from calibration draws, not this scene's stand-ins; on
    // builtin:orchard:1000 its pixel part came out about 30 % low. The factor also takes in any per-pixel bias of the zoom model (it too shrinks with
    // the zoom): totals across zooms stay right, but that part is then scaled per LOD level.
    double lodPixelScale() const { return lodPixelScale_; }

private:
    GovernorChoice choosePredictive(const GovernorLoad& load);
    GovernorChoice chooseReactive(const GovernorLoad& load);
    // LOD's predicted time at a level and zoom (its pixel part divided by z^2).
    double lodMs(const GovernorLoad& load, int level, int zoom) const;
    int lowestZoom(const GovernorLoad& load) const;
    int highestZoom(const GovernorLoad& load) const;
    int highestLevel(const GovernorLoad& load) const;
    // Whether the zoom cost model was calibrated (budgetNeedsCalibration); tests may pass none.
    bool modelCalibrated() const;
    // Reactive: the technique's time that scales with the pixels at a zoom, under the zoom model,
    // with `fragments` (drawn at `fragmentsZoom`) scaled to that zoom's pixels.
    double techniqueSizeMs(glm::ivec2 display, int zoom, double fragments, int fragmentsZoom) const;
    // Reactive: the time at (zoom, level) of a frame measured `ms` at the current state.
    double reactiveEstimate(const GovernorLoad& load, double ms, int zoom, int level) const;
    void changeState(int zoom, int level, bool controlled);
    // Reactive: over or under the band at `now` (ms, as the coming view loads the current
    // state), moves to the least lossy state estimated to fit (over: the fastest if none does).
    // `learnable`: the frames before the change may teach how the time splits (not a jump's).
    // `viewDriven`: over only at the coming view (the frames were not), so a relief just before
    // was no mistake and the hold is not backed off.
    void decide(const GovernorLoad& load, double now, bool learnable, bool viewDriven);
    // Reactive: LOD's preview of the current state at one frame's view, its fixed and size parts
    // apart (seen: there was a preview), so that views are compared with the factor on the size
    // part as it stands, not as it stood when each was drawn.
    struct ViewLoad {
        double fixedMs = 0.0, sizeMs = 0.0;
        bool seen = false;
    };
    ViewLoad viewLoad(const GovernorLoad& load) const;
    double viewMs(const ViewLoad& v) const { return v.fixedMs + lodPixelScale_ * v.sizeMs; }
    // How much more the coming view loads the current state than the measured frames' views did
    // (their median); 0 where any of them had no preview.
    double viewChange(const ViewLoad& coming, const std::deque<ViewLoad>& measured) const;

    ZoomBudget budget_;
    BudgetLevers levers_;
    ZoomControllerKind kind_;
    ZoomCostModel model_;
    LossScales scales_;
    std::unique_ptr<ZoomController> zoomOnly_;         // the zoom lever alone: today's controller
    std::unique_ptr<PredictiveZoomController> zoomPart_;  // predictive: the zoom model, LOD's predicted part removed
    GovernorLoad lastLoad_;
    GovernorChoice last_;
    // Reactive state.
    int zoom_ = 1, level_ = 0;
    int sinceChange_ = 0, hold_ = 1;
    bool lastWasStepDown_ = false;
    std::deque<double> recent_;
    std::deque<ViewLoad> recentViews_;  // each frame's in recent_, at its own view
    // The hold ended with the last frame observed: the time judged, and the frames' views.
    struct Pending {
        double ms = 0.0;
        std::deque<ViewLoad> views;
        bool jump = false;
    };
    std::optional<Pending> pending_;
    int beforeZoom_ = 0, beforeLevel_ = 0;
    double beforeMs_;
    double pixelShare_ = 1.0;  // of the time at zoom 1, what scales with pixels
    bool shareLearned_ = false;  // pixelShare_ measured (a change of zoom alone), not assumed
    double fragments_ = 0.0;        // transparent fragments of the last frame at the current state
    double beforeFragments_ = 0.0;  // and of the last frame before the last change
    // Predictive: LOD's pixel part as drawn over as previewed (lodMs), fitted to the frames.
    void learnLodPixelScale(const GovernorLoad& load, int level, const FrameCost& cost);
    // LOD's size-dependent part at zoom z: its pixel part / z^2 and its side part / z.
    static double lodSizePart(const LodLevelPreview& level, int zoom);
    // The preview of a ladder level (clamped to the ladder; the preview must have levels), and its
    // part no zoom shrinks (its predicted time less its pixel and side parts).
    static const LodLevelPreview& levelOf(const GovernorLoad& load, int level);
    static double lodFixedMs(const LodLevelPreview& level);
    double lodPixelScale_ = 1.0;
    struct PixelFit {
        double w = 0.0, x = 0.0, y = 0.0, xx = 0.0, xy = 0.0;  // decayed sums
    } pixelFit_;
};

}  // namespace strata
