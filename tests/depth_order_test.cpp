// The tie rule of render/depth_order.hpp on hand-made fragment lists: near-equal depths are one
// layer in object order, separated depths keep depth order, and the result does not depend on
// the order the fragments arrive in.
#include "render/depth_order.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <numeric>
#include <random>

using namespace strata;

namespace {

SurfaceFragment fragment(double depth, int object, int primitive = 0) {
    SurfaceFragment f;
    f.depth = float(depth);
    f.object = object;
    f.primitive = primitive;
    f.alpha = 0.5f;
    f.color = glm::vec3(float(object), 0.0f, 0.0f);
    return f;
}

std::vector<int> objectsOf(const std::vector<SurfaceFragment>& fs) {
    std::vector<int> ids;
    for (const auto& f : fs) ids.push_back(f.object);
    return ids;
}

const double kTol = tieToleranceFromUlps(64.0);

}  // namespace

TEST_CASE("depth order: round-off differences are one layer, ordered by object id") {
    // Object 1 is a few ulps nearer than object 0: round-off, so object 0 composites first.
    std::vector<SurfaceFragment> fs = {fragment(2.0 * (1 + 3e-7), 0), fragment(2.0, 1)};
    CHECK(orderFragments(fs, kTol) == 1);
    CHECK(objectsOf(fs) == std::vector<int>{0, 1});
    // Without a tolerance the same fragments sort by depth.
    std::vector<SurfaceFragment> strict = {fragment(2.0 * (1 + 3e-7), 0), fragment(2.0, 1)};
    CHECK(orderFragments(strict, 0.0) == 0);
    CHECK(objectsOf(strict) == std::vector<int>{1, 0});
}

TEST_CASE("depth order: surfaces farther apart than the tolerance keep their depth order") {
    // 1e-4 relative is about 840 ulps: two distinct surfaces.
    std::vector<SurfaceFragment> fs = {fragment(2.0 * (1 + 1e-4), 0), fragment(2.0, 1)};
    CHECK(orderFragments(fs, kTol) == 0);
    CHECK(objectsOf(fs) == std::vector<int>{1, 0});
    // At the boundary: just inside is a tie, just outside is not.
    CHECK(sameDepthLayer(1.0, 1.0 + 0.99 * kTol, kTol));
    CHECK_FALSE(sameDepthLayer(1.0, 1.0 + 1.01 * kTol, kTol));
    // The tolerance is relative: the same absolute gap is a tie far away, not near.
    CHECK(sameDepthLayer(1000.0, 1000.0 + 1e-3, kTol));
    CHECK_FALSE(sameDepthLayer(1.0, 1.0 + 1e-3, kTol));
}

TEST_CASE("depth order: layers, ties counted, and every arrival order gives the same sequence") {
    // Three layers: {3, 1, 4} near 1.0, {2} at 1.5, {0, 5} near 3.0, each near-equal group
    // within a few ulps; primitives break a tie inside one object.
    std::vector<SurfaceFragment> fs = {
        fragment(1.0 + 2e-7, 3), fragment(1.0, 4), fragment(1.0 + 1e-7, 1),     fragment(1.5, 2),
        fragment(3.0, 5, 1),     fragment(3.0, 5, 0), fragment(3.0 * (1 + 4e-7), 0),
    };
    const std::vector<int> expected = {1, 3, 4, 2, 0, 5, 5};
    std::vector<int> perm(fs.size());
    std::iota(perm.begin(), perm.end(), 0);
    std::mt19937 rng(7);
    for (int trial = 0; trial < 50; ++trial) {
        std::shuffle(perm.begin(), perm.end(), rng);
        std::vector<SurfaceFragment> shuffled;
        for (int i : perm) shuffled.push_back(fs[std::size_t(i)]);
        CHECK(orderFragments(shuffled, kTol) == 4);  // ties per layer: 2 + 0 + 2
        CHECK(objectsOf(shuffled) == expected);
        CHECK(shuffled[5].primitive == 0);
        CHECK(shuffled[6].primitive == 1);
    }
}

TEST_CASE("depth order: composite of two coincident quads follows the object order") {
    // Analytic: alpha 0.5 each, colours (0,..) and (1,..): object 0 in front whatever the
    // round-off says: C = 0.5 * 0 + 0.25 * 1 + 0.25 * background.
    std::vector<SurfaceFragment> fs = {fragment(2.0, 1), fragment(2.0 * (1 + 2e-7), 0)};
    glm::vec3 c = compositeInDepthOrder(fs, glm::vec3(0.4f), kTol);
    CHECK(c.r == doctest::Approx(0.25 + 0.25 * 0.4));
    std::vector<SurfaceFragment> strict = {fragment(2.0, 1), fragment(2.0 * (1 + 2e-7), 0)};
    glm::vec3 s = compositeInDepthOrder(strict, glm::vec3(0.4f), 0.0);
    CHECK(s.r == doctest::Approx(0.5 + 0.25 * 0.0 + 0.25 * 0.4));
}
