#pragma once
// Viewing error: how far the displayed view is from the view the true head pose at display
// time would have produced.
//
// Definitions (every angular value is an upper bound on the angular error of any ray in the
// view, so the three deflections are compared on one scale):
//  - none: the geodesic angle between the rendered orientation R1 and the true orientation Rt.
//    A rotation by theta moves no direction by more than theta, and directions perpendicular
//    to its axis by exactly theta.
//  - homography: the warp turns the image rendered at R1 into exactly the image at the
//    re-predicted orientation R2, so the residual is the geodesic angle between R2 and Rt:
//    the error of the second prediction.
//  - shift: a 2D translation is not the image of any rotation. It stands in for the pan/tilt
//    Reff = R1 exp((pitch, yaw, 0)) (camera frame); the error is angle(Reff, Rt) -- the second
//    prediction's error plus the uncorrected roll -- plus the approximation term, the largest
//    angle over nine probe pixels (centre, edge midpoints, corners) between the ray the shifted
//    image shows there and the ray Reff shows there (triangle inequality => an upper bound).
//    The approximation term grows towards the edges: ~ rotation * sin^2(off-axis angle).
//  - position: |p1 - pt| in millimetres for every deflection; a 2D deflection cannot undo a
//    translation (that needs depth).
#include "tracking/deflection.hpp"

namespace strata::tracking {

struct ViewingError {
    double angleDeg = 0.0;
    double positionMm = 0.0;
    double approximationDeg = 0.0;  // shift only: the part due to translating instead of rotating
};

ViewingError viewingError(Deflect deflect, const Intrinsics& k, const PoseSample& rendered,
                          const PoseSample& reread, const PoseSample& truth);

// The shift deflection's approximation term alone (see above), degrees.
double shiftApproximationDeg(const Intrinsics& k, const Eigen::Quaterniond& rendered,
                             const Eigen::Quaterniond& latest);

}  // namespace strata::tracking
