// Deflection math and the viewing-error definitions (CPU only; the GL warp is not written yet).
#include "tracking/viewing_error.hpp"

#include <doctest/doctest.h>

#include <random>

using namespace strata::tracking;

namespace {

Eigen::Quaterniond randomRotation(std::mt19937_64& rng, double maxAngle) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const Eigen::Vector3d axis = Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized();
    return quatExp(axis * maxAngle * std::abs(u(rng)));
}

}  // namespace

TEST_CASE("projection conventions: -Z forward at the principal point, +Y up is up in the image") {
    const Intrinsics k = Intrinsics::fromFov(1920, 1080, 90.0);
    CHECK(k.fx == doctest::Approx(960.0));
    Eigen::Vector2d px;
    REQUIRE(projectDirection(k, Eigen::Quaterniond::Identity(), Eigen::Vector3d(0, 0, -1), px));
    CHECK((px - Eigen::Vector2d(960, 540)).norm() < 1e-9);
    REQUIRE(projectDirection(k, Eigen::Quaterniond::Identity(), Eigen::Vector3d(1, 1, -1), px));
    CHECK((px - Eigen::Vector2d(1920, 540 - 960)).norm() < 1e-9);
    CHECK_FALSE(projectDirection(k, Eigen::Quaterniond::Identity(), Eigen::Vector3d(0, 0, 1), px));
    const Eigen::Vector3d d = unprojectPixel(k, Eigen::Quaterniond::Identity(), Eigen::Vector2d(1920, -420));
    CHECK((d - Eigen::Vector3d(1, 1, -1).normalized()).norm() < 1e-12);
}

TEST_CASE("homography maps the image of a rotation exactly") {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const Intrinsics k = Intrinsics::fromFov(1280, 720, 100.0);
    for (int trial = 0; trial < 50; ++trial) {
        const Eigen::Quaterniond r1 = randomRotation(rng, M_PI);
        const Eigen::Quaterniond r2 = randomRotation(rng, 0.2) * r1;
        const Eigen::Matrix3d h = deflectionHomography(k, r1, r2);
        for (int i = 0; i < 20; ++i) {
            // A direction visible in the first view, seen through K before and after.
            const Eigen::Vector3d dir = unprojectPixel(k, r1, Eigen::Vector2d(u(rng) * k.width, u(rng) * k.height));
            Eigen::Vector2d x1, x2;
            REQUIRE(projectDirection(k, r1, dir, x1));
            if (!projectDirection(k, r2, dir, x2)) continue;
            CHECK((applyHomography(h, x1) - x2).norm() < 1e-6);
        }
    }
}

TEST_CASE("shift matches the homography to first order for small rotations") {
    std::mt19937_64 rng(5);
    const Intrinsics k = Intrinsics::fromFov(1920, 1080, 90.0);
    const Eigen::Vector2d c(k.cx, k.cy);
    for (int trial = 0; trial < 20; ++trial) {
        const Eigen::Quaterniond r1 = randomRotation(rng, M_PI);
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        const Eigen::Vector3d axis = Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized();
        double previous = 0.0;
        for (double eps : {1e-2, 5e-3, 2.5e-3}) {
            const Eigen::Quaterniond r2 = r1 * quatExp(axis * eps);
            const Eigen::Vector2d viaH = applyHomography(deflectionHomography(k, r1, r2), c) - c;
            const Eigen::Vector2d s = deflectionShift(k, r1, r2);
            const double diff = (s - viaH).norm();
            CHECK(diff < 2.0 * k.fx * eps * eps);  // second order in the angle
            if (previous > 1e-9) CHECK(diff < 0.35 * previous);  // halving eps quarters it
            previous = diff;
        }
    }
    // Direction of the shift: turning left (positive yaw about +Y) moves content right.
    const Eigen::Vector2d s = deflectionShift(k, Eigen::Quaterniond::Identity(), quatExp(Eigen::Vector3d(0, 0.01, 0)));
    CHECK(s.x() == doctest::Approx(9.6));
    CHECK(s.y() == doctest::Approx(0.0));
}

TEST_CASE("viewing error: what each deflection leaves") {
    const Intrinsics k = Intrinsics::fromFov(1920, 1080, 90.0);
    const Eigen::Quaterniond truth = quatExp(Eigen::Vector3d(0.1, 0.5, 0.0));
    const Eigen::Quaterniond rendered = quatExp(Eigen::Vector3d(0.0, -0.05, 0.0)) * truth;  // 2.9 deg off
    const Eigen::Quaterniond reread = quatExp(Eigen::Vector3d(0.0, 0.002, 0.0)) * truth;
    const PoseSample r1{0, Eigen::Vector3d(0, 0, 0), rendered};
    const PoseSample r2{0, Eigen::Vector3d(1, 1, 1), reread};
    const PoseSample t{0, Eigen::Vector3d(0.003, 0, 0.004), truth};

    const ViewingError none = viewingError(Deflect::None, k, r1, r2, t);
    CHECK(none.angleDeg == doctest::Approx(radToDeg(0.05)));
    CHECK(none.positionMm == doctest::Approx(5.0));
    const ViewingError homography = viewingError(Deflect::Homography, k, r1, r2, t);
    CHECK(homography.angleDeg == doctest::Approx(radToDeg(0.002)));
    CHECK(homography.positionMm == doctest::Approx(5.0));  // translation is not deflected
    const ViewingError shift = viewingError(Deflect::Shift, k, r1, r2, t);
    CHECK(shift.angleDeg < none.angleDeg);
    CHECK(shift.angleDeg > homography.angleDeg);  // the pan/scroll approximation at the edges
    CHECK(shift.approximationDeg > 0.0);

    // Pure roll cannot be shifted away.
    const Eigen::Quaterniond rolled = rendered * quatExp(Eigen::Vector3d(0, 0, 0.03));
    const ViewingError roll = viewingError(Deflect::Shift, k, PoseSample{0, {}, rolled}, PoseSample{0, {}, rendered},
                                           PoseSample{0, {}, rendered});
    CHECK(roll.angleDeg >= radToDeg(0.03) - 1e-9);
    CHECK(shiftApproximationDeg(k, rolled, rolled) < 1e-9);
}
