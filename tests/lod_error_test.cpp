// The impostor's screen-space error (lod/lod_error.hpp): projected size, parallax, sampling.
#include "lod/lod_error.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <initializer_list>
#include <numbers>

using namespace strata::lod;

namespace {
constexpr double kPi = std::numbers::pi;
}

TEST_CASE("lod error: projected diameter of a bounding sphere") {
    // 90 degrees over 100 px: f = 100 / (2 tan 45) = 50 px per unit of tangent.
    CHECK(focalLengthPx(kPi / 2, 100) == doctest::Approx(50.0));
    // r = 1 at d = sqrt 2: the silhouette's half-angle is 45 degrees, the diameter 2 f = 100.
    CHECK(projectedDiameterPx(1.0, std::sqrt(2.0), kPi / 2, 100) == doctest::Approx(100.0));
    // r = 3 at d = 5: 2 x 50 x 3 / 4 = 75.
    CHECK(projectedDiameterPx(3.0, 5.0, kPi / 2, 100) == doctest::Approx(75.0));
    // Far away it is about 2 f r / d: r = 1 at d = 1000 -> 0.1 px (within 1e-6 relative).
    CHECK(projectedDiameterPx(1.0, 1000.0, kPi / 2, 100) == doctest::Approx(0.1).epsilon(1e-6));
    // Twice the image height: twice the pixels.
    CHECK(projectedDiameterPx(3.0, 5.0, kPi / 2, 200) == doctest::Approx(150.0));
    // Eye inside or on the sphere: unbounded; a point (radius 0): nothing.
    CHECK(std::isinf(projectedDiameterPx(1.0, 0.5, kPi / 2, 100)));
    CHECK(std::isinf(projectedDiameterPx(1.0, 1.0, kPi / 2, 100)));
    CHECK(projectedDiameterPx(0.0, 5.0, kPi / 2, 100) == 0.0);
}

TEST_CASE("lod error: with no overlap and parallel rays, parallax is d sin a / 2L; sampling d / resolution") {
    const ImpostorShape flat{8, 64, 0.0, 0.0};
    // 100 px, 8 slices, 64 texels, 30 degrees: 100 x 0.5 / 16 = 3.125 px; 100 / 64 = 1.5625 px.
    const ImpostorError e = impostorError(100.0, flat, kPi / 6);
    CHECK(e.parallaxPx == doctest::Approx(3.125));
    CHECK(e.samplingPx == doctest::Approx(1.5625));
    CHECK(e.totalPx() == doctest::Approx(4.6875));
    // At a baked view: no parallax, only sampling.
    CHECK(impostorError(100.0, flat, 0.0).parallaxPx == 0.0);
    CHECK(impostorError(100.0, flat, 0.0).totalPx() == doctest::Approx(1.5625));
    // L = 1 and L = 256 at 90 degrees: 50 px and 100 / 512 = 0.1953125 px.
    CHECK(impostorError(100.0, {1, 64, 0.0, 0.0}, kPi / 2).parallaxPx == doctest::Approx(50.0));
    CHECK(impostorError(100.0, {256, 64, 0.0, 0.0}, kPi / 2).parallaxPx == doctest::Approx(0.1953125));
    // Past 90 degrees counts as 90 (monotone in the angle).
    CHECK(impostorError(100.0, flat, 2.0).parallaxPx == doctest::Approx(impostorError(100.0, flat, kPi / 2).parallaxPx));
    // Eye inside (infinite size) at a baked view: no NaN.
    CHECK(impostorError(INFINITY, flat, 0.0).parallaxPx == 0.0);
    CHECK(std::isinf(impostorError(INFINITY, flat, 0.0).samplingPx));
}

TEST_CASE("lod error: the overlap and the apex's diverging rays, (0.5 + o) d sin(a + h) / (L cos h)") {
    // The default bake: overlap 0.5, apex at 3r, h = asin(1/3), cos h = sqrt(8) / 3.
    const double h = apexHalfAngleRadians(3.0);
    CHECK(h == doctest::Approx(std::asin(1.0 / 3.0)));
    CHECK(std::sin(h) == doctest::Approx(1.0 / 3.0));
    const ImpostorShape bake{8, 64, 0.5, h};
    // At a baked view the rays still diverge: 100 x 1 x (1/3) / (8 x sqrt(8)/3) = 100 / (8 sqrt 8).
    CHECK(impostorError(100.0, bake, 0.0).parallaxPx == doctest::Approx(100.0 / (8.0 * std::sqrt(8.0))));
    // 30 degrees off: 100 x 1 x sin(30 deg + h) / (8 cos h).
    CHECK(impostorError(100.0, bake, kPi / 6).parallaxPx ==
          doctest::Approx(100.0 * std::sin(kPi / 6 + h) / (8.0 * std::cos(h))));
    // Overlap alone doubles the half-slice bound at overlap 0.5: 2 x 3.125.
    CHECK(impostorError(100.0, {8, 64, 0.5, 0.0}, kPi / 6).parallaxPx == doctest::Approx(6.25));
    // a + h past 90 degrees counts as 90: 100 x 1 / (8 cos h).
    CHECK(impostorError(100.0, bake, 1.4).parallaxPx == doctest::Approx(100.0 / (8.0 * std::cos(h))));
    // Sampling does not depend on either.
    CHECK(impostorError(100.0, bake, 0.3).samplingPx == doctest::Approx(1.5625));
    // A far apex tends to parallel rays; one at the sphere (factor <= 1) is the widest field.
    CHECK(apexHalfAngleRadians(1e9) == doctest::Approx(0.0));
    CHECK(apexHalfAngleRadians(1.0) == doctest::Approx(kPi / 2));
}

TEST_CASE("lod error: grows with the angle, falls with more slices and more texels") {
    double previous = -1.0;
    for (double degrees : {0.0, 5.0, 10.0, 20.0, 37.0, 60.0, 90.0}) {
        const double e = impostorError(200.0, {16, 128, 0.5, apexHalfAngleRadians(3.0)}, degrees * kPi / 180.0).totalPx();
        CHECK(e > previous);
        previous = e;
    }
    previous = 1e30;
    for (int slices : {1, 2, 4, 16, 64, 256}) {
        const double e = impostorError(200.0, {slices, 128, 0.5, apexHalfAngleRadians(3.0)}, 0.3).totalPx();
        CHECK(e < previous);
        previous = e;
    }
    CHECK(impostorError(200.0, {16, 256, 0.5, 0.3}, 0.3).totalPx() < impostorError(200.0, {16, 64, 0.5, 0.3}, 0.3).totalPx());
}
