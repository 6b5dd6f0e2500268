#include "lod/lod_error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace strata::lod {

double focalLengthPx(double fovYRadians, int imageHeight) {
    return double(imageHeight) / (2.0 * std::tan(0.5 * fovYRadians));
}

double projectedDiameterPx(double radius, double distance, double fovYRadians, int imageHeight) {
    if (radius <= 0.0) return 0.0;
    if (distance <= radius) return std::numeric_limits<double>::infinity();
    return 2.0 * focalLengthPx(fovYRadians, imageHeight) * radius / std::sqrt(distance * distance - radius * radius);
}

ImpostorError impostorError(double projectedDiameter, int slices, int resolution, double angleRadians) {
    ImpostorError e;
    const double angle = std::clamp(std::abs(angleRadians), 0.0, 0.5 * std::numbers::pi);
    // At the baked view itself nothing moves, whatever the size (no 0 x infinity).
    e.parallaxPx = angle > 0.0 ? projectedDiameter * std::sin(angle) / (2.0 * double(std::max(slices, 1))) : 0.0;
    e.samplingPx = projectedDiameter / double(std::max(resolution, 1));
    return e;
}

}  // namespace strata::lod
