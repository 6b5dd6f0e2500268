#include "tracking/viewing_error.hpp"

#include <algorithm>
#include <cmath>

namespace strata::tracking {
namespace {

// Pan/tilt the shift stands in for: the rendered orientation turned by the yaw and pitch of
// the re-prediction, without its roll.
Eigen::Quaterniond shiftEquivalent(const Eigen::Quaterniond& rendered, const Eigen::Quaterniond& latest) {
    const Eigen::Vector3d phi = quatLog(rendered.conjugate() * latest);
    return safeNormalized(rendered * quatExp(Eigen::Vector3d(phi.x(), phi.y(), 0.0)));
}

double angleBetweenDirections(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    // atan2 form stays accurate for tiny angles where acos(dot) rounds to zero.
    return std::atan2(a.cross(b).norm(), a.dot(b));
}

}  // namespace

double shiftApproximationDeg(const Intrinsics& k, const Eigen::Quaterniond& rendered,
                             const Eigen::Quaterniond& latest) {
    const Eigen::Vector2d s = deflectionShift(k, rendered, latest);
    const Eigen::Quaterniond eff = shiftEquivalent(rendered, latest);
    double worst = 0.0;
    for (int iy = 0; iy < 3; ++iy)
        for (int ix = 0; ix < 3; ++ix) {
            const Eigen::Vector2d x(0.5 * ix * k.width, 0.5 * iy * k.height);
            // The displayed pixel x shows what the rendered image had at x - s.
            const Eigen::Vector3d shown = unprojectPixel(k, rendered, x - s);
            const Eigen::Vector3d wanted = unprojectPixel(k, eff, x);
            worst = std::max(worst, angleBetweenDirections(shown, wanted));
        }
    return radToDeg(worst);
}

ViewingError viewingError(Deflect deflect, const Intrinsics& k, const PoseSample& rendered,
                          const PoseSample& reread, const PoseSample& truth) {
    ViewingError e;
    e.positionMm = 1000.0 * (rendered.p - truth.p).norm();
    switch (deflect) {
        case Deflect::None: e.angleDeg = radToDeg(angleBetween(rendered.q, truth.q)); break;
        case Deflect::Homography: e.angleDeg = radToDeg(angleBetween(reread.q, truth.q)); break;
        case Deflect::Shift:
            e.approximationDeg = shiftApproximationDeg(k, rendered.q, reread.q);
            e.angleDeg = radToDeg(angleBetween(shiftEquivalent(rendered.q, reread.q), truth.q)) + e.approximationDeg;
            break;
    }
    return e;
}

}  // namespace strata::tracking
