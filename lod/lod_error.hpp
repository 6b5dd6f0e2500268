#pragma once
// The screen-space error of drawing an object as a layered impostor instead of its geometry,
// in pixels of the final image, from the bounding sphere alone (no rendering):
//
//  - parallax: the impostor puts each surface point on a slice's plane, along the bake's ray
//    from the apex through its texel. Slices are w = 2r / L apart along the baked view's axis
//    (lod-contract.md), and a slice accepts the depths of its own interval and `overlap` widths
//    past it each side, so a point lands up to dz = (0.5 + overlap) w off its true depth. The
//    bake's rays diverge from the apex by up to h = asin(1 / apexFactor) (19.5 degrees at 3r):
//    the point moves dz / cos h along its ray, and seen from a direction at angle a to the axis
//    that moves it sideways on screen by at most dz sin(a + h) / cos h. In pixels that is
//    projectedDiameterPx (0.5 + overlap) sin(a + h) / (L cos h). It falls as 1 / L (Schauffler
//    section 3.2: the warp's accuracy grows with the number of layers) and grows with the angle
//    to the nearest baked view; it is not 0 at a baked view itself, since the eye's rays are
//    not the bake's (a far eye's are parallel). a + h past 90 degrees counts as 90 (the nearest
//    of 12 or more views is always within about 38 degrees). With overlap 0 and h 0 this is the
//    half-slice bound d sin a / 2L.
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

// What of an impostor's bake the error depends on.
struct ImpostorShape {
    int slices = 1;                     // L (>= 1)
    int resolution = 64;                // texels a side (>= 1)
    double overlap = 0.0;               // slice widths past its own interval, each side (>= 0)
    double apexHalfAngleRadians = 0.0;  // h: the bake frustum's half-angle, asin(r / D)
};

// h for an apex at apexFactor * r (> 1); 90 degrees for a factor <= 1 (impostorError takes at
// most 0.49 pi of it).
double apexHalfAngleRadians(double apexFactor);

// The error above for an impostor of `shape` seen `angleRadians` from its nearest baked view,
// at `projectedDiameter` pixels.
ImpostorError impostorError(double projectedDiameter, const ImpostorShape& shape, double angleRadians);

}  // namespace strata::lod
