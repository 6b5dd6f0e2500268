#include "frame/budget_governor.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace strata {
namespace {

// The least share of a frame's time the reactive policy takes to scale with the zoom's pixels.
constexpr double kLeastPixelShare = 0.02;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Two losses (or times) closer than this are equal: the tie goes to the other criterion.
constexpr double kTie = 1e-9;

// Reactive: a frame this many times over the target ends the hold.
constexpr double kJumpOverTarget = 2.0;
// Reactive: this many frames in a row over the band end the hold too, judged on their median.
constexpr int kOverFramesToAct = 2;
// The LOD pixel scale's fit: each frame's weight decays by this per frame (about the last ten
// frames count), x must spread by this share of its mean, and the scale stays in this range.
constexpr double kPixelFitMemory = 0.9;
constexpr double kPixelFitSpread = 0.05;
constexpr double kPixelScaleMin = 0.5, kPixelScaleMax = 4.0;
// Reactive: the least change of LOD's size part, as a share of the frame, a change of zoom learns
// the factor from.
constexpr double kLeastLodChange = 0.05;

}  // namespace

BudgetLevers parseBudgetLevers(std::string_view text) {
    if (text == "zoom") return {true, false};
    if (text == "lod") return {false, true};
    if (text == "zoom,lod" || text == "lod,zoom") return {true, true};
    throw std::invalid_argument("budget levers '" + std::string(text) + "' are not one of zoom|lod|zoom,lod");
}

std::string to_string(BudgetLevers levers) {
    if (levers.zoom && levers.lod) return "zoom,lod";
    return levers.zoom ? "zoom" : "lod";
}

double LodLadder::bound(int level) const { return basePx * std::ldexp(1.0, std::max(level, 0)); }

std::vector<double> LodLadder::bounds() const {
    std::vector<double> b;
    for (int k = 0; k < levels; ++k) b.push_back(bound(k));
    return b;
}

bool budgetNeedsCalibration(ZoomControllerKind kind, BudgetLevers levers) {
    return kind == ZoomControllerKind::Predictive || (levers.zoom && levers.lod);
}

double zoomLossPx(int zoom) { return 0.5 * double(std::max(zoom, 1) - 1); }

double priorPixelShare(double ms, double fixedMs, double pixelRatio) {
    if (!(ms > 0.0) || !(pixelRatio > 0.0) || !std::isfinite(fixedMs)) return 1.0;
    // ms = fixed + perPixel * pixelRatio, so perPixel = (ms - fixed) / pixelRatio at zoom 1.
    const double fixed = std::clamp(fixedMs, 0.0, ms);
    const double perPixel = (ms - fixed) / pixelRatio;
    return std::clamp(perPixel / std::max(fixed + perPixel, 1e-9), kLeastPixelShare, 1.0);
}

BudgetGovernor::BudgetGovernor(const ZoomBudget& budget, BudgetLevers levers, ZoomControllerKind kind,
                               const ZoomCostModel& model, LossScales scales)
    : budget_(budget), levers_(levers), kind_(kind), model_(model), scales_(scales), beforeMs_(kNaN) {
    if (!levers.zoom && !levers.lod) throw std::invalid_argument("a frame budget needs at least one lever");
    // Both controllers check the budget; the zoom part is built either way for that.
    zoomOnly_ = makeZoomController(kind, budget, model);
    if (levers_.lod) zoomOnly_.reset();
    if (levers_.lod && kind == ZoomControllerKind::Predictive)
        zoomPart_ = std::make_unique<PredictiveZoomController>(budget, model);
    zoom_ = budget.minZoom;
    hold_ = budget.holdFrames;
}

int BudgetGovernor::lowestZoom(const GovernorLoad& load) const {
    return std::min(std::max(budget_.minZoom, load.zoom.zoomFloor), budget_.maxZoom);
}

int BudgetGovernor::highestZoom(const GovernorLoad& load) const {
    // Without the zoom lever the zoom stays at its floor (the head speed still raises it).
    return levers_.zoom ? budget_.maxZoom : lowestZoom(load);
}

int BudgetGovernor::highestLevel(const GovernorLoad& load) const {
    return levers_.lod && !load.lod.levels.empty() ? int(load.lod.levels.size()) - 1 : 0;
}

const LodLevelPreview& BudgetGovernor::levelOf(const GovernorLoad& load, int level) {
    return load.lod.levels[std::size_t(std::clamp(level, 0, int(load.lod.levels.size()) - 1))];
}

double BudgetGovernor::lodFixedMs(const LodLevelPreview& level) { return level.predictedMs - level.pixelMs - level.sideMs; }

double BudgetGovernor::lodMs(const GovernorLoad& load, int level, int zoom) const {
    if (load.lod.levels.empty()) return 0.0;
    const LodLevelPreview& l = levelOf(load, level);
    return lodFixedMs(l) + lodPixelScale_ * lodSizePart(l, zoom);
}

double BudgetGovernor::lodSizePart(const LodLevelPreview& l, int zoom) {
    const double z = double(zoom);
    return l.pixelMs / (z * z) + l.sideMs / z;
}

void BudgetGovernor::learnLodPixelScale(const GovernorLoad& load, int level, const FrameCost& cost) {
    if (load.lod.levels.empty()) return;
    const LodLevelPreview& l = levelOf(load, level);
    if (l.pixelMs + l.sideMs <= 0.0) return;
    // y = what the frame took beyond the zoom model (its learnt offset left out) and LOD's
    // fixed part; x = LOD's predicted pixel and side parts at the zoom drawn. y = offset + scale x.
    const double x = lodSizePart(l, cost.zoom);
    const double y = cost.ms - lodFixedMs(l) -
                     (zoomPart_->predict(load.zoom, cost.zoom) - zoomPart_->sceneOffsetMs());
    PixelFit& f = pixelFit_;
    f.w = kPixelFitMemory * f.w + 1.0;
    f.x = kPixelFitMemory * f.x + x;
    f.y = kPixelFitMemory * f.y + y;
    f.xx = kPixelFitMemory * f.xx + x * x;
    f.xy = kPixelFitMemory * f.xy + x * y;
    const double meanX = f.x / f.w, variance = f.xx / f.w - meanX * meanX;
    // Only where the frames drawn spread x (two zooms, or a view that changed the pixel part):
    // else the offset alone explains them.
    if (f.w < 2.5 || variance <= kPixelFitSpread * kPixelFitSpread * meanX * meanX) return;
    const double slope = (f.xy / f.w - meanX * f.y / f.w) / variance;
    lodPixelScale_ = std::clamp(slope, kPixelScaleMin, kPixelScaleMax);
}

double BudgetGovernor::loss(const GovernorLoad& load, int zoom, int level) const {
    double px = scales_.zoom * zoomLossPx(zoom) * std::clamp(load.lod.coverage, 0.0, 1.0);
    if (!load.lod.levels.empty())
        px += scales_.lod * levelOf(load, level).lossPx;
    return px;
}

GovernorChoice BudgetGovernor::choose(const GovernorLoad& load) {
    lastLoad_ = load;
    if (zoomOnly_) {
        last_ = GovernorChoice{zoomOnly_->choose(load.zoom), 0, zoomOnly_->predictedMs(), 0.0};
        last_.lossPx = loss(load, last_.zoom, 0);
        return last_;
    }
    last_ = kind_ == ZoomControllerKind::Predictive ? choosePredictive(load) : chooseReactive(load);
    return last_;
}

// --- predictive -------------------------------------------------------------------------------

GovernorChoice BudgetGovernor::choosePredictive(const GovernorLoad& load) {
    GovernorChoice best{lowestZoom(load), 0, kNaN, 0.0};
    bool bestFits = false;
    for (int z = lowestZoom(load); z <= highestZoom(load); ++z)
        for (int k = 0; k <= highestLevel(load); ++k) {
            const double ms = zoomPart_->predict(load.zoom, z) + lodMs(load, k, z);
            const double px = loss(load, z, k);
            const bool fits = ms <= budget_.targetMs;
            bool better;
            if (!std::isfinite(best.predictedMs)) better = true;
            else if (fits != bestFits) better = fits;
            else if (fits) better = px < best.lossPx - kTie || (px <= best.lossPx + kTie && ms < best.predictedMs);
            else better = ms < best.predictedMs - kTie || (ms <= best.predictedMs + kTie && px < best.lossPx);
            if (better) {
                best = GovernorChoice{z, k, ms, px};
                bestFits = fits;
            }
        }
    return best;
}

// --- reactive ---------------------------------------------------------------------------------

bool BudgetGovernor::modelCalibrated() const { return model_.msPerMegapixel > 0.0 || model_.msPerMegafragment > 0.0; }

double BudgetGovernor::techniqueSizeMs(glm::ivec2 display, int zoom, double fragments, int fragmentsZoom) const {
    // Fragments drawn at one zoom scale with the pixels to another.
    const double scaled = fragments * zoomPixels(display, zoom) / std::max(zoomPixels(display, fragmentsZoom), 1.0);
    return model_.predict(zoomPixels(display, zoom), scaled) - model_.fixedMs;
}

double BudgetGovernor::reactiveEstimate(const GovernorLoad& load, double ms, int zoom, int level) const {
    const glm::ivec2 display = load.zoom.displaySize;
    if (modelCalibrated() && !load.lod.levels.empty() && display.x > 0) {
        // The time measured plus the two models' difference between the states: what shrinks with
        // the zoom is only what they say does (the technique's pixels and fragments, LOD's
        // stand-in pixels and quad sides, the latter times the factor learnt from the changes of
        // zoom drawn). The rest of the frame, what neither model explains included, is fixed, as
        // the predictive policy's learnt offset takes it: on the field's sweep, frames near the
        // eye drew 43-47 ms at 2 px whether at zoom 1 or 2.
        return ms + techniqueSizeMs(display, zoom, fragments_, zoom_) - techniqueSizeMs(display, zoom_, fragments_, zoom_) +
               lodMs(load, level, zoom) - lodMs(load, level_, zoom_);
    }
    double scaled = ms;
    if (display.x > 0 && zoom != zoom_) {
        const double p1 = zoomPixels(display, 1);
        // Until a change of zoom has shown how the time splits, the LOD preview's part that no zoom
        // shrinks (its geometry's triangles and draws) is taken as the frame's only such part: a
        // geometry-bound view is not promised a zoom's saving. Without a preview, all of it scales.
        double share = pixelShare_;
        if (!shareLearned_ && !load.lod.levels.empty()) {
            const LodLevelPreview& at = levelOf(load, level_);
            share = priorPixelShare(ms, lodFixedMs(at), zoomPixels(display, zoom_) / p1);
        }
        auto model = [&](int z) { return (1.0 - share) + share * zoomPixels(display, z) / p1; };
        scaled = ms * model(zoom) / model(zoom_);
    }
    return scaled + lodMs(load, level, zoom) - lodMs(load, level_, zoom);
}

void BudgetGovernor::changeState(int zoom, int level, bool controlled) {
    beforeZoom_ = zoom_;
    beforeLevel_ = level_;
    beforeMs_ = controlled && !recent_.empty() ? medianMs(recent_) : kNaN;
    beforeFragments_ = fragments_;
    lastWasStepDown_ = zoom < zoom_ || level < level_;
    zoom_ = zoom;
    level_ = level;
    recent_.clear();
    recentViews_.clear();
    pending_.reset();
    sinceChange_ = 0;
}

BudgetGovernor::ViewLoad BudgetGovernor::viewLoad(const GovernorLoad& load) const {
    if (load.lod.levels.empty()) return {};
    const LodLevelPreview& l = levelOf(load, level_);
    return ViewLoad{lodFixedMs(l), lodSizePart(l, zoom_), true};
}

double BudgetGovernor::viewChange(const ViewLoad& coming, const std::deque<ViewLoad>& measured) const {
    // Nothing to compare where a view had no preview (LOD not steering that frame): none is assumed.
    if (!coming.seen || measured.empty()) return 0.0;
    std::deque<double> ms;
    for (const ViewLoad& v : measured) {
        if (!v.seen) return 0.0;
        ms.push_back(viewMs(v));
    }
    const double change = viewMs(coming) - medianMs(ms);
    return std::isfinite(change) ? change : 0.0;
}

GovernorChoice BudgetGovernor::chooseReactive(const GovernorLoad& load) {
    // The frames were measured at their own views; this frame's view may load the current state
    // more or less. LOD's preview of the current state, at this view against at theirs, says how
    // much (the same models' difference the estimates of other states take, across views).
    const double target = budget_.targetMs, overLimit = target * (1.0 + budget_.band);
    bool decided = false;
    if (pending_) {
        // The hold ended with the last frame: judged at this view, before the floor below (the
        // decision keeps to it), as when it was taken at the end of the frame.
        const Pending p = std::move(*pending_);
        pending_.reset();
        // A change on a jump is not one to learn from (its "before" is one frame of a new load).
        // Over only at this view: no relief that has to be undone.
        decide(load, p.ms + viewChange(viewLoad(load), p.views), !p.jump, p.ms <= overLimit);
        decided = true;
    }
    const int zoom = std::clamp(zoom_, lowestZoom(load), highestZoom(load));
    const int level = std::clamp(level_, 0, highestLevel(load));
    // The head-speed floor (or a ladder that shrank) overrides: what was measured no longer applies.
    if (zoom != zoom_ || level != level_) changeState(zoom, level, false);
    const double change = viewChange(viewLoad(load), recentViews_);
    if (!decided && !recent_.empty()) {
        // Before the hold ends, a load the preview sees growing past the band at this view: the
        // step a reactive policy would take after the frames over it, taken before them. Only a
        // growth wider than the band itself, so that the frames' noise alone never acts here.
        // Not one to learn from either: the frames before it were drawn at other views.
        const double estimate = medianMs(recent_) + change;
        if (change > budget_.band * target && estimate > overLimit) decide(load, estimate, false, true);
    }
    // After a step recent_ is empty; without one, `change` is still this state's.
    const double predicted = recent_.empty() ? kNaN : medianMs(recent_) + change;
    return GovernorChoice{zoom_, level_, predicted, loss(load, zoom_, level_)};
}

void BudgetGovernor::observe(const FrameCost& cost) {
    if (zoomOnly_) {
        zoomOnly_->observe(cost);
        return;
    }
    const GovernorLoad& load = lastLoad_;
    if (zoomPart_) {
        // The zoom model learns the frame less LOD's predicted part at the state drawn, so its
        // offset takes in what both models miss (a constant bias of LOD's included).
        learnLodPixelScale(load, last_.lodLevel, cost);
        FrameCost zoomCost = cost;
        zoomCost.ms = cost.ms - lodMs(load, last_.lodLevel, cost.zoom);
        zoomPart_->observe(zoomCost);
        return;
    }
    if (cost.zoom != zoom_) return;  // not the frame this governor chose
    recent_.push_back(cost.ms);
    recentViews_.push_back(viewLoad(load));
    fragments_ = double(cost.fragments);
    while (int(recent_.size()) > budget_.holdFrames) recent_.pop_front();
    while (int(recentViews_.size()) > budget_.holdFrames) recentViews_.pop_front();
    // A frame over twice the target is no outlier to wait out (a cut, a turn into a dense view):
    // it is judged at once, on its own time.
    const bool jump = cost.ms > kJumpOverTarget * budget_.targetMs;
    // Frames over the band since the last change, all of them: the state (or the new load) is
    // too slow, and each frame the hold waits is a frame over budget (on the orchard's sweep into
    // the grid, the hold kept 8 of 72 frames over). Relief (under the band) still waits the hold.
    const double overLimit = budget_.targetMs * (1.0 + budget_.band);
    const bool overRun = int(recent_.size()) >= kOverFramesToAct &&
                         std::all_of(recent_.end() - kOverFramesToAct, recent_.end(), [&](double t) { return t > overLimit; });
    if (++sinceChange_ < hold_ && !jump && !overRun) return;
    // Judged on the frames that ended the hold: a run over the band on its own frames (the
    // window may still hold frames of an easier view before it).
    const double now = jump      ? cost.ms
                       : overRun ? medianMs(std::deque<double>(recent_.end() - kOverFramesToAct, recent_.end()))
                                 : medianMs(recent_);
    // The views those frames were drawn at.
    std::deque<ViewLoad> nowViews = recentViews_;
    if (jump || overRun) nowViews.erase(nowViews.begin(), nowViews.end() - (jump ? 1 : kOverFramesToAct));

    // Learn from a change of zoom alone (the bound held), through the medians before and after:
    // with a calibrated zoom model, the factor on LOD's size part; without one, the pixel share
    // (t = a + b P, as the reactive zoom controller does).
    const glm::ivec2 display = load.zoom.displaySize;
    // Not from a jump: one frame of a changed load says nothing of how the time splits.
    const bool zoomAloneChanged = !jump && std::isfinite(beforeMs_) && beforeZoom_ != zoom_ && beforeLevel_ == level_ && display.x > 0;
    if (zoomAloneChanged && modelCalibrated() && !load.lod.levels.empty()) {
        // The saving the zoom model does not explain is LOD's size part's, times the factor, in
        // the predictive policy's range (on the field's sweep a zoom of 2 saved nothing of the
        // preview's 18 ms of stand-in pixels at 2 px: the factor's floor, 0.5, is then learnt).
        const LodLevelPreview& at = levelOf(load, level_);
        const double lodChange = lodSizePart(at, beforeZoom_) - lodSizePart(at, zoom_);
        const double rest = beforeMs_ - now -
                            (techniqueSizeMs(display, beforeZoom_, beforeFragments_, beforeZoom_) -
                             techniqueSizeMs(display, zoom_, fragments_, zoom_));
        // Only a change that moves LOD's part by a visible share of the frame says how large it
        // is: a smaller one is the frames' noise divided by almost nothing.
        if (std::abs(lodChange) >= kLeastLodChange * now)
            lodPixelScale_ = std::clamp(rest / lodChange, kPixelScaleMin, kPixelScaleMax);
    } else if (zoomAloneChanged) {
        const double p1 = zoomPixels(display, 1);
        const double pb = zoomPixels(display, beforeZoom_) / p1, pn = zoomPixels(display, zoom_) / p1;
        const double b = (beforeMs_ - now) / (pb - pn);
        const double a = now - b * pn;
        const double share = std::clamp(b / std::max(a + b, 1e-9), kLeastPixelShare, 1.0);
        if (std::isfinite(share)) {
            pixelShare_ = share;
            shareLearned_ = true;
        }
    }
    if (!jump) beforeMs_ = kNaN;
    // The next choose() decides, with the view it is for.
    pending_ = Pending{now, std::move(nowViews), jump};
}

void BudgetGovernor::decide(const GovernorLoad& load, double now, bool learnable, bool viewDriven) {
    const double target = budget_.targetMs;
    const bool over = now > target * (1.0 + budget_.band);
    const bool under = now < target * (1.0 - budget_.band);
    if (over || under) {
        // Over: the lossier states (neither lever eased); under: the less lossy ones (neither
        // lever raised). The least loss estimated to fit; over with none fitting, the fastest.
        int bestZoom = zoom_, bestLevel = level_;
        double bestMs = kNaN, bestPx = 0.0;
        bool bestFits = false;
        for (int z = lowestZoom(load); z <= highestZoom(load); ++z)
            for (int k = 0; k <= highestLevel(load); ++k) {
                if (z == zoom_ && k == level_) continue;
                if (over && (z < zoom_ || k < level_)) continue;
                // Relief one step of each lever at most, as the zoom controller steps down by
                // one: its estimate extrapolates the measured time, and a long step that
                // overshoots costs frames over the band (the orchard's sweep: 8 -> 4 -> 6).
                if (under && (z > zoom_ || k > level_ || z < zoom_ - 1 || k < level_ - 1)) continue;
                const double ms = reactiveEstimate(load, now, z, k);
                // A bound that predicts no saving is no step at all.
                if (over && z == zoom_ && ms >= now - kTie) continue;
                const double px = loss(load, z, k);
                const bool fits = ms <= target;
                if (under && !fits) continue;
                bool better;
                if (!std::isfinite(bestMs)) better = true;
                else if (fits != bestFits) better = fits;
                else if (fits) better = px < bestPx - kTie || (px <= bestPx + kTie && ms < bestMs);
                else better = ms < bestMs - kTie || (ms <= bestMs + kTie && px < bestPx);
                if (better) {
                    bestZoom = z;
                    bestLevel = k;
                    bestMs = ms;
                    bestPx = px;
                    bestFits = fits;
                }
            }
        if (bestZoom != zoom_ || bestLevel != level_) {
            // A relief that had to be undone doubles the hold before the next one (up to 8x).
            // Not where only the coming view is over: the relief was no mistake, the load grew.
            if (over && lastWasStepDown_ && sinceChange_ <= hold_ && !viewDriven)
                hold_ = std::min(hold_ * 2, budget_.holdFrames * 8);
            changeState(bestZoom, bestLevel, learnable);
            return;
        }
    }
    if (sinceChange_ >= 4 * hold_) hold_ = budget_.holdFrames;  // settled: the back-off ends
}

}  // namespace strata
