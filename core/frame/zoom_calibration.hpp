#pragma once
// What the predictive zoom controller (frame/zoom_controller.hpp) needs from the GPU: the cost
// model, calibrated on this device for one technique at start-up, and the two per-frame inputs it
// reads before a frame is drawn or after it is measured.
#include "frame/zoom_controller.hpp"
#include "oit/technique.hpp"
#include "render/gpu_scene.hpp"

#include <functional>
#include <string>

namespace strata {

struct ZoomCalibrationPoint {
    int layers = 0, zoom = 1;
    double pixels = 0.0, fragments = 0.0, ms = 0.0;
};

struct ZoomCalibration {
    ZoomCostModel model;
    std::vector<ZoomCalibrationPoint> points;
    double rmsResidualMs = 0.0;   // of the fit over the points
};

// Draws builtin:layers:1 and builtin:layers:8 (full-view quads: fragments = layers x pixels) with
// `technique` at zooms 1, 2 and 4 of `displaySize` (those up to maxZoom; one frame to warm up,
// the fastest of two timed), and fits t = fixed + per pixel + per fragment by least squares, the
// slopes kept non-negative. Leaves the technique's buffers sized for the last point.
ZoomCalibration calibrateZoomCost(Technique& technique, glm::ivec2 displaySize, int maxZoom,
                                  const std::function<void(const std::string&)>& progress = {});

// Display pixels under the screen rectangles of the transparent objects' world bounds, summed over
// objects and clipped to the display: an estimate of the transparent fragments at zoom 1 up to a
// density the controller learns. An object wholly behind the eye counts nothing; one that straddles
// the eye plane counts as the whole display.
double transparentScreenArea(const GpuScene& scene, const glm::mat4& viewProjection, glm::ivec2 displaySize);

// Fragments a technique rasterized in its last frame: captured, dropped and blended as a tail.
std::uint64_t fragmentsRasterized(const TechniqueStats& stats);

}  // namespace strata
