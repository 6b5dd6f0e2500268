#pragma once
// The screen-space error of drawing an object as a layered impostor instead of its geometry,
// in pixels of the final image, from the bounding sphere alone (no rendering):
//
//  - parallax: the impostor puts each surface point on its slice's plane. Slices are 2r / L
//    apart across the sphere's depth (lod-contract.md), so a point lies at most half a slice,
//    r / L, off its true depth along the baked view's axis. Seen from a direction at angle a
//    to that axis, a depth offset d moves the point sideways on screen by d sin a: the error is
//    (2r / L) / 2 * sin a world units, i.e. projectedDiameterPx * sin a / (2 L) pixels. It grows
//    with the angle to the nearest baked view and falls as 1 / L (Schauffler section 3.2: the
//    warp's accuracy grows with the number of layers). Angles past 90 degrees count as 90 (the
//    nearest of 12 or more views is always within about 38 degrees).
//  - sampling: the image holds `resolution` texels across the sphere's diameter, so one texel
//    covers projectedDiameterPx / resolution pixels on screen. Detail finer than a texel is lost
//    and edges step by a texel: the texel's footprint is the error (below 1 px it is below the
//    image's own sampling and negligible).
//  The total is their sum: a bound, as both can land on the same pixel.
//
// The projected diameter is the exact one of a sphere's silhouette seen from its centre's
// direction: its half-angle is asin(r / d) at distance d, so on an image plane where one unit
// of tangent is f = imageHeight / (2 tan(fovY / 2)) pixels, the diameter is
// 2 f tan(asin(r / d)) = 2 f r / sqrt(d^2 - r^2) (about 2 f r / d far away).
#include <glm/glm.hpp>

namespace strata::lod {

// Pixels per unit of tangent on the image plane: imageHeight / (2 tan(fovY / 2)).
double focalLengthPx(double fovYRadians, int imageHeight);

// The projected diameter, in pixels, of a sphere of `radius` whose centre is `distance` from the
// eye. +infinity when the eye is inside or on the sphere (distance <= radius); 0 for radius 0.
double projectedDiameterPx(double radius, double distance, double fovYRadians, int imageHeight);

struct ImpostorError {
    double parallaxPx = 0.0;
    double samplingPx = 0.0;
    double totalPx() const { return parallaxPx + samplingPx; }
};

// The error above for an impostor of `slices` slices (>= 1) and `resolution` texels a side
// (>= 1) seen `angleRadians` from its nearest baked view, at `projectedDiameter` pixels.
ImpostorError impostorError(double projectedDiameter, int slices, int resolution, double angleRadians);

}  // namespace strata::lod
