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

double apexHalfAngleRadians(double apexFactor) {
    return apexFactor > 1.0 ? std::asin(1.0 / apexFactor) : 0.5 * std::numbers::pi;
}

ImpostorError impostorError(double projectedDiameter, const ImpostorShape& shape, double angleRadians) {
    ImpostorError e;
    const double halfPi = 0.5 * std::numbers::pi;
    // Below 90 degrees, so that cos h stays positive (an apex at the sphere, factor <= 1, is 90).
    const double apex =
        shape.apexHalfAngleRadians > 0.0 ? std::min(shape.apexHalfAngleRadians, 0.49 * std::numbers::pi) : 0.0;
    const double angle = std::min(std::abs(angleRadians) + apex, halfPi);
    const double depthSlices = 0.5 + (shape.overlap > 0.0 ? shape.overlap : 0.0);  // NaN counts as 0
    // Where nothing moves (a baked view, parallel rays) it is 0 whatever the size (no 0 x infinity).
    e.parallaxPx = angle > 0.0 ? projectedDiameter * depthSlices * std::sin(angle) /
                                     (double(std::max(shape.slices, 1)) * std::cos(apex))
                               : 0.0;
    e.samplingPx = projectedDiameter / double(std::max(shape.resolution, 1));
    return e;
}

}  // namespace strata::lod
