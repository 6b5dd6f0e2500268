#pragma once
// The order in which an exact path composites a pixel's transparent fragments, and its tie rule.
// The CPU ray cast, every GPU resolve (shaders/oit/ordered_composite.glsl) and the analytic
// tests follow this one rule.
//
// Why a tolerance: one plane drawn by two meshes (a decal, a shared cube face, a copy placed by
// another transform) does not get bit-equal depths. The vertex transform and the rasterizer's
// interpolation round differently for different vertices and matrices, differently on each
// driver, so "sort by depth" would order such surfaces by round-off: speckled, and different on
// every GPU. Instead, depths within a relative tolerance are one layer, and the layer's
// fragments are ordered by the scene's object order (then primitive id): a rule the scene's
// author controls, like a decal order.
//
// The rule, on eye depths z (distance along the view axis):
//  1. sort the fragments by (z, object, primitive): a total order, so the result does not depend
//     on the order fragments arrived in;
//  2. cut the sorted list into layers: consecutive fragments with |z_i - z_{i+1}| <= tol *
//     max(z_i, z_{i+1}) are in one layer (chains of such steps too);
//  3. within a layer, composite by (object, primitive, z).
// Steps 2 and 3 only look at the sorted sequence, which is a function of the set of fragments,
// so the whole rule is independent of arrival order.
//
// Why relative eye depth: round-off in the projected depth is relative to the depth's magnitude
// at every distance. On the GPU the same test is done on w = d + n / (f - n), with d the
// reversed-Z window depth: w is proportional to 1 / z, and |z1 - z2| / max(z) equals
// |w1 - w2| / max(w) exactly, so the GPU needs no division and no eye depth.
//
// The tolerance is given in float ulps (units of 2^-23, relative): Scene::depthTieUlps.
// Surfaces closer than it are treated as coincident: at the default 1024 ulps (1.2e-4 relative)
// that is 1.2 mm at 10 m. NVIDIA puts one plane drawn by two meshes up to 1024 ulps apart (it
// snaps vertices to its sub-pixel grid before setting up the depth plane; 64 ulps, the old
// default, left 123 of 1728 pixels of builtin:cubes ordered by round-off on an H100), and the
// shipped models have no distinct surfaces that close (docs/results.md, the tolerance table:
// merging starts near 16384 ulps).
#include "render/composite.hpp"

#include <vector>

namespace strata {

constexpr double kFloatUlp = 1.0 / 8388608.0;  // 2^-23

inline double tieToleranceFromUlps(double ulps) { return ulps * kFloatUlp; }

// True when eye depths a and b (both positive) are one layer under relative tolerance tol.
inline bool sameDepthLayer(double a, double b, double tol) {
    double larger = a > b ? a : b;
    return (a > b ? a - b : b - a) <= tol * larger;
}

// Puts `fragments` (SurfaceFragment::depth = eye depth) in the compositing order above and
// returns how many are tied: not the first of their layer (K coincident surfaces give K - 1).
int orderFragments(std::vector<SurfaceFragment>& fragments, double tolerance);

// Front to back in the given order: C += T a c; T *= 1 - a; result C + T background.
glm::vec3 compositeOrdered(const std::vector<SurfaceFragment>& ordered, const glm::vec3& background);

// orderFragments, then compositeOrdered.
glm::vec3 compositeInDepthOrder(std::vector<SurfaceFragment>& fragments, const glm::vec3& background,
                                double tolerance);

}  // namespace strata
