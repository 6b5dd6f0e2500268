#pragma once
// Zoom rendering and the frame budget in the windows (walkthrough and immersive): which zoom the
// next frame draws at, and under a budget which LOD error bound, fixed or picked per frame by
// the budget governor (frame/budget_governor.hpp: the least loss predicted or measured to fit),
// the zoom raised during fast head turns in immersive mode, and the last frames' zoom, bound,
// predicted and measured time for the panel's plots. The zoom model is calibrated
// (frame/zoom_calibration.hpp) for the current technique and window size, for the predictive
// policy and for the reactive one with both levers (budgetNeedsCalibration), when the policy is
// chosen and whenever either changes.
#include "frame_history.hpp"

#include "camera/camera.hpp"
#include "frame/frame_renderer.hpp"
#include "frame/budget_governor.hpp"
#include "frame/zoom_controller.hpp"
#include "lod/lod_controller.hpp"

#include <memory>
#include <string>

namespace strata {

// What the panel edits.
struct ZoomChoices {
    int controller = 0;        // 0 fixed, 1 reactive, 2 predictive (kZoomControllerNames)
    int fixedZoom = 1;
    float targetMs = 33.3f;
    int maxZoom = 8;
    bool blur = false;         // enlarge with a bilinear blur instead of replication
    bool followHead = true;    // immersive: fast head turns raise the zoom (section 4.2)
    int levers = 2;            // under a budget: 0 zoom, 1 LOD bound, 2 both (kBudgetLeverNames)
    float lodBasePx = 4.0f;    // the LOD lever's least bound (its ladder: x1, x2, x4, x8)
};

inline constexpr const char* kZoomControllerNames[] = {"fixed", "reactive", "predictive"};
inline constexpr const char* kBudgetLeverNames[] = {"zoom", "lod", "zoom,lod"};

class ZoomDriver {
public:
    explicit ZoomDriver(ZoomChoices initial = {}) : choices_(initial) {}

    // The zoom the next frame draws at (options.zoom and zoomFilter set); headDegPerSecond is the
    // head's angular speed (0 outside immersive mode). With the LOD lever, `lod` (in auto mode)
    // is previewed and its error bound set for the frame.
    int begin(const GpuScene& scene, const Camera& camera, glm::ivec2 displaySize, Technique* technique,
              FrameOptions& options, double headDegPerSecond = 0.0, lod::LodController* lod = nullptr);
    // The frame drawn with begin()'s zoom.
    void end(const FrameResult& result, Technique* technique);

    ZoomChoices& choices() { return choices_; }
    int zoom() const { return zoom_; }
    int headFloor() const { return headFloor_; }
    double predictedMs() const { return predictedMs_; }
    double measuredMs() const { return measuredMs_; }
    const FrameHistory& zoomHistory() const { return zoomHistory_; }
    const FrameHistory& measuredHistory() const { return measuredHistory_; }
    const FrameHistory& predictedHistory() const { return predictedHistory_; }
    const FrameHistory& boundHistory() const { return boundHistory_; }
    // The LOD error bound the budget set for the last frame; 0 where it steers no bound.
    double lodBoundPx() const { return lodBoundPx_; }
    double lossPx() const { return lossPx_; }
    const std::string& status() const { return status_; }
    // One line on stdout: "zoom: Z (controller[, levers]), frame T ms GPU[, predicted P ms][, lod bound B px]".
    void printFigures() const;

private:
    void rebuild(glm::ivec2 displaySize, Technique* technique);

    ZoomChoices choices_;
    ZoomChoices built_{};              // the choices controller_ was made for
    std::string builtTechnique_;
    glm::ivec2 builtSize_{0, 0};
    std::unique_ptr<BudgetGovernor> controller_;
    ZoomCostModel model_;
    GovernorLoad load_;
    int zoom_ = 1, headFloor_ = 1;
    double predictedMs_ = 0.0, measuredMs_ = 0.0, lodBoundPx_ = 0.0, lossPx_ = 0.0;
    bool steeredBound_ = false;  // the last frame's bound was the budget's
    double userBoundPx_ = 4.0;   // the LOD bound before the budget steered it
    FrameHistory zoomHistory_, measuredHistory_, predictedHistory_, boundHistory_;
    std::string status_;
};

// The panel section: controller, target, zoom, and the plots. `immersive` shows the head option.
void drawZoomSection(ZoomDriver& zoom, bool immersive);

}  // namespace strata
