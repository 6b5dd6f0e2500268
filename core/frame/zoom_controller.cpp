#include "frame/zoom_controller.hpp"

#include "render/zoom.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace strata {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

int clampZoom(int zoom, const ZoomBudget& budget, int floor) {
    return std::clamp(zoom, std::max(budget.minZoom, floor), budget.maxZoom);
}

}  // namespace

std::string_view zoomControllerName(ZoomControllerKind kind) {
    return kind == ZoomControllerKind::Reactive ? "reactive" : "predictive";
}

ZoomControllerKind parseZoomController(std::string_view name) {
    if (name == "reactive") return ZoomControllerKind::Reactive;
    if (name == "predictive") return ZoomControllerKind::Predictive;
    throw std::invalid_argument("unknown zoom controller '" + std::string(name) + "' (known: reactive, predictive)");
}

double medianMs(std::deque<double> values) {
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

double zoomPixels(glm::ivec2 displaySize, int zoom) {
    const glm::ivec2 r = zoomRenderSize(displaySize, zoom);
    return double(r.x) * double(r.y);
}

ZoomController::ZoomController(const ZoomBudget& budget) : budget_(budget) {
    if (!(budget.targetMs > 0.0) || !std::isfinite(budget.targetMs))
        throw std::invalid_argument("frame budget must be a positive number of milliseconds");
    if (budget.minZoom < 1 || budget.maxZoom > kMaxZoom || budget.minZoom > budget.maxZoom)
        throw std::invalid_argument("zoom range must lie in 1.." + std::to_string(kMaxZoom));
    if (budget.holdFrames < 1) throw std::invalid_argument("zoom hold must be at least one frame");
}

// --- reactive ---------------------------------------------------------------------------------

ReactiveZoomController::ReactiveZoomController(const ZoomBudget& budget)
    : ZoomController(budget), zoom_(budget.minZoom), hold_(budget.holdFrames), predicted_(kNaN) {}

double ReactiveZoomController::pixelShare() const { return pixelPart_ / (fixedPart_ + pixelPart_); }

double ReactiveZoomController::scaled(double ms, int from, int to) const {
    if (display_.x <= 0) return ms;
    const double p1 = zoomPixels(display_, 1);
    auto model = [&](int z) { return fixedPart_ + pixelPart_ * zoomPixels(display_, z) / p1; };
    return ms * model(to) / model(from);
}

void ReactiveZoomController::change(int zoom) {
    beforeZoom_ = zoom_;
    beforeMs_ = recent_.empty() ? kNaN : medianMs(recent_);
    lastWasStepDown_ = zoom < zoom_;
    zoom_ = zoom;
    recent_.clear();
    sinceChange_ = 0;
}

int ReactiveZoomController::choose(const FrameLoad& load) {
    display_ = load.displaySize;
    const int forced = clampZoom(zoom_, budget_, load.zoomFloor);
    if (forced != zoom_) {
        // The head-speed floor overrides; what was measured at the old zoom no longer applies.
        change(forced);
        beforeMs_ = kNaN;  // not a controlled step: nothing to learn from it
    }
    predicted_ = recent_.empty() ? kNaN : medianMs(recent_);
    return zoom_;
}

void ReactiveZoomController::observe(const FrameCost& cost) {
    if (cost.zoom != zoom_) return;  // not the frame this controller chose
    recent_.push_back(cost.ms);
    while (int(recent_.size()) > budget_.holdFrames) recent_.pop_front();
    if (++sinceChange_ < hold_) return;
    const double now = medianMs(recent_);

    // Learn how the time splits into fixed and per-pixel parts from the change just held:
    // t = a + b P through (P_before, t_before) and (P_now, t_now), kept relative (a + b P_1 = 1).
    if (std::isfinite(beforeMs_) && beforeZoom_ != zoom_ && display_.x > 0) {
        const double p1 = zoomPixels(display_, 1);
        const double pb = zoomPixels(display_, beforeZoom_) / p1, pn = zoomPixels(display_, zoom_) / p1;
        const double b = (beforeMs_ - now) / (pb - pn);
        const double a = now - b * pn;
        // A change of load during the hold can give any pair; keep the split physical.
        const double share = std::clamp(b / std::max(a + b, 1e-9), 0.02, 1.0);
        if (std::isfinite(share)) {
            pixelPart_ = share;
            fixedPart_ = 1.0 - share;
        }
        beforeMs_ = kNaN;
    }

    const double target = budget_.targetMs;
    if (now > target * (1.0 + budget_.band) && zoom_ < budget_.maxZoom) {
        int next = zoom_ + 1;
        while (next < budget_.maxZoom && scaled(now, zoom_, next) > target) ++next;
        // A step down that had to be undone doubles the hold before the next one (up to 8x).
        if (lastWasStepDown_ && sinceChange_ <= hold_) hold_ = std::min(hold_ * 2, budget_.holdFrames * 8);
        change(next);
        return;
    }
    if (now < target * (1.0 - budget_.band) && zoom_ > budget_.minZoom) {
        const int down = zoom_ - 1;
        if (scaled(now, zoom_, down) <= target) {
            change(down);
            return;
        }
    }
    if (sinceChange_ >= 4 * hold_) hold_ = budget_.holdFrames;  // settled: the back-off ends
}

// --- predictive -------------------------------------------------------------------------------

PredictiveZoomController::PredictiveZoomController(const ZoomBudget& budget, const ZoomCostModel& model)
    : ZoomController(budget), model_(model), predicted_(kNaN) {}

double PredictiveZoomController::predict(const FrameLoad& load, int zoom) const {
    const double z2 = double(zoom) * double(zoom);
    const double fragments = fragmentsPerArea_ * load.transparentArea / z2;
    return model_.predict(zoomPixels(load.displaySize, zoom), fragments) + offsetMs_;
}

int PredictiveZoomController::choose(const FrameLoad& load) {
    const int lowest = std::max(budget_.minZoom, load.zoomFloor);
    int zoom = std::min(lowest, budget_.maxZoom);
    while (zoom < budget_.maxZoom && predict(load, zoom) > budget_.targetMs) ++zoom;
    predicted_ = predict(load, zoom);
    return zoom;
}

void PredictiveZoomController::observe(const FrameCost& cost) {
    // Fragment density per display pixel of transparent area: what the last frame's count says
    // this frame's area will hold (fragments fall as 1/z^2 with the frame's pixels).
    if (cost.load.transparentArea > 0.0) {
        const double density = double(cost.fragments) * double(cost.zoom) * double(cost.zoom) / cost.load.transparentArea;
        fragmentsPerArea_ = seeded_ ? 0.5 * (fragmentsPerArea_ + density) : density;
        seeded_ = true;
    }
    // The scene's fixed part beyond the calibration scene's (its triangles, draws, opaque pass):
    // the residual of the model on the fragments actually drawn.
    const double model = model_.predict(zoomPixels(cost.load.displaySize, cost.zoom), double(cost.fragments));
    const double residual = cost.ms - model;
    offsetMs_ += 0.3 * (residual - offsetMs_);
}

std::unique_ptr<ZoomController> makeZoomController(ZoomControllerKind kind, const ZoomBudget& budget,
                                                   const ZoomCostModel& model) {
    if (kind == ZoomControllerKind::Reactive) return std::make_unique<ReactiveZoomController>(budget);
    return std::make_unique<PredictiveZoomController>(budget, model);
}

int zoomFloorForHeadSpeed(double degPerSecond, const HeadSpeedZoom& rule) {
    if (!std::isfinite(degPerSecond) || degPerSecond <= rule.stillDegPerSecond) return 1;
    const double steps = (degPerSecond - rule.stillDegPerSecond) / rule.degPerSecondPerStep;
    return std::min(rule.maxZoom, 1 + 1 + int(std::floor(steps)));
}

BudgetHits budgetHits(const std::vector<double>& ms, double targetMs, double band) {
    BudgetHits hits;
    if (ms.empty()) return hits;
    for (double t : ms) {
        if (std::abs(t - targetMs) <= band * targetMs) hits.within += 1.0;
        if (t <= targetMs * (1.0 + band)) hits.notOver += 1.0;
    }
    hits.within /= double(ms.size());
    hits.notOver /= double(ms.size());
    return hits;
}

}  // namespace strata
