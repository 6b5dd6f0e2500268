#pragma once
// Choosing the zoom factor per frame for a target frame time (zoom rendering, Mazuryk et al.
// 1996, section 4.1), plus the head-speed floor of section 4.2. CPU only: the renderer measures,
// these decide.
//  - reactive: from the last frames' measured times alone. It holds a zoom for `holdFrames` frames
//    (hysteresis), then moves by what the median of those frames says. How much of the time
//    scales with pixels is learned from the frames around each change (t = a + b pixels), so a
//    step down that would overshoot is not taken twice.
//  - predictive: the frame's time predicted before it is drawn from what will be drawn: pixels at
//    each zoom, transparent fragments expected (the last frames' count per unit of transparent
//    screen area, times this frame's area from the objects' screen rectangles), and a fixed part,
//    with costs per pixel and per fragment calibrated on this device and technique at start-up
//    (frame/zoom_calibration.hpp) and the scene's fixed part learned from the residuals.
#include <glm/glm.hpp>

#include <cstdint>
#include <deque>
#include <limits>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace strata {

enum class ZoomControllerKind { Reactive, Predictive };

std::string_view zoomControllerName(ZoomControllerKind kind);
// Throws std::invalid_argument naming the known ones.
ZoomControllerKind parseZoomController(std::string_view name);

struct ZoomBudget {
    double targetMs = 33.3;
    int minZoom = 1, maxZoom = 8;
    int holdFrames = 4;   // reactive: frames between two changes, and the window it judges
    double band = 0.10;   // within +-band of the target counts as on budget
};

// What is known of a frame before it is drawn.
struct FrameLoad {
    glm::ivec2 displaySize{0, 0};
    double transparentArea = 0.0;  // display pixels under transparent objects (transparentScreenArea)
    int zoomFloor = 1;             // the least zoom this frame may use (head speed, zoomFloorForHeadSpeed)
};

// What a frame cost once drawn.
struct FrameCost {
    int zoom = 1;
    double ms = 0.0;               // the whole frame's GPU time (FrameResult::gpuMs)
    std::uint64_t fragments = 0;   // transparent fragments rasterized (captured + dropped + tail)
    FrameLoad load;
};

// Per-device, per-technique costs (frame/zoom_calibration.hpp); t = fixed + px + fragments.
struct ZoomCostModel {
    double fixedMs = 0.0;
    double msPerMegapixel = 0.0;
    double msPerMegafragment = 0.0;
    double predict(double pixels, double fragments) const {
        return fixedMs + msPerMegapixel * pixels * 1e-6 + msPerMegafragment * fragments * 1e-6;
    }
};

class ZoomController {
public:
    explicit ZoomController(const ZoomBudget& budget);
    virtual ~ZoomController() = default;
    // The zoom for the next frame (within minZoom..maxZoom and at least load.zoomFloor).
    virtual int choose(const FrameLoad& load) = 0;
    // The frame just drawn with the zoom choose() returned.
    virtual void observe(const FrameCost& cost) = 0;
    // What the controller expects the frame it last chose for to cost; NaN when it has no idea.
    virtual double predictedMs() const = 0;
    virtual ZoomControllerKind kind() const = 0;
    const ZoomBudget& budget() const { return budget_; }

protected:
    ZoomBudget budget_;
};

class ReactiveZoomController final : public ZoomController {
public:
    explicit ReactiveZoomController(const ZoomBudget& budget);
    int choose(const FrameLoad& load) override;
    void observe(const FrameCost& cost) override;
    double predictedMs() const override { return predicted_; }
    ZoomControllerKind kind() const override { return ZoomControllerKind::Reactive; }
    // The learned share of the frame time that scales with pixels at zoom 1 (1 until learned).
    double pixelShare() const;

private:
    // The time at zoom `to` of a frame that took `ms` at zoom `from` (the learned a + b pixels).
    double scaled(double ms, int from, int to) const;
    void change(int zoom);

    glm::ivec2 display_{0, 0};
    int zoom_;
    int sinceChange_ = 0;
    int hold_;                    // grows after a step down that had to be undone
    std::deque<double> recent_;   // times at zoom_, newest last
    // Around the last change: the zoom and median time before it, to learn a and b from.
    int beforeZoom_ = 0;
    double beforeMs_ = std::numeric_limits<double>::quiet_NaN();
    bool lastWasStepDown_ = false;
    double fixedPart_ = 0.0, pixelPart_ = 1.0;  // a and b, relative (only their ratio matters)
    double predicted_;
};

class PredictiveZoomController final : public ZoomController {
public:
    PredictiveZoomController(const ZoomBudget& budget, const ZoomCostModel& model);
    int choose(const FrameLoad& load) override;
    void observe(const FrameCost& cost) override;
    double predictedMs() const override { return predicted_; }
    ZoomControllerKind kind() const override { return ZoomControllerKind::Predictive; }
    // The frame's time at `zoom` under the model, the learned scene offset and fragment density.
    double predict(const FrameLoad& load, int zoom) const;
    const ZoomCostModel& model() const { return model_; }
    double sceneOffsetMs() const { return offsetMs_; }

private:
    ZoomCostModel model_;
    double offsetMs_ = 0.0;           // the scene's fixed part beyond the calibration's
    // Transparent fragments per display pixel of transparent area, at zoom 1. Until a frame is
    // measured: one (exact for full-view quads; closed objects hold two per covered pixel but
    // cover less than their rectangles).
    double fragmentsPerArea_ = 1.0;
    bool seeded_ = false;
    double predicted_;
};

std::unique_ptr<ZoomController> makeZoomController(ZoomControllerKind kind, const ZoomBudget& budget,
                                                   const ZoomCostModel& model);

// Section 4.2: fast head turns raise the zoom (perception is poor during them, and a shorter
// frame shortens the prediction interval); a still head lets it fall back. One step of zoom per
// `degPerSecondPerStep` of angular speed above `stillDegPerSecond`, capped at `maxZoom`.
struct HeadSpeedZoom {
    double stillDegPerSecond = 30.0;
    double degPerSecondPerStep = 60.0;
    int maxZoom = 4;
};
int zoomFloorForHeadSpeed(double degPerSecond, const HeadSpeedZoom& rule = {});

// The median of frame times (the reactive controllers' judgement over their hold).
double medianMs(std::deque<double> values);

// Reduced pixels of a display at a zoom (zoomRenderSize's area).
double zoomPixels(glm::ivec2 displaySize, int zoom);

// Frames within +-band of the target, and at most target (1 + band), as shares of `ms`.
struct BudgetHits {
    double within = 0.0;
    double notOver = 0.0;
};
BudgetHits budgetHits(const std::vector<double>& ms, double targetMs, double band);

}  // namespace strata
