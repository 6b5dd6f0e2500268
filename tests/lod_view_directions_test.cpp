// The impostor view directions (lod/view_directions.hpp): the platonic solids' directions,
// their spacing and covering radius (the largest view error nearest-view selection can make),
// nearest-view order and the hole-filling adjacency.
#include "lod/view_directions.hpp"

#include <doctest/doctest.h>

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <map>
#include <set>
#include <stdexcept>

using namespace strata::lod;

namespace {
float degrees(float radians) { return radians * 180.0f / glm::pi<float>(); }
}  // namespace

TEST_CASE("lod view directions: counts, unit length, no duplicates, antipodal pairs") {
    for (int n : {12, 20, 32}) {
        const auto dirs = viewDirections(n);
        REQUIRE(int(dirs.size()) == n);
        for (const auto& d : dirs) CHECK(glm::length(d) == doctest::Approx(1.0f).epsilon(1e-6));
        // Both solids are centrally symmetric: every direction's opposite is in the set.
        for (const auto& d : dirs) CHECK(angleToNearestView(dirs, -d) < 1e-3f);
    }
    CHECK_THROWS_AS(viewDirections(6), std::invalid_argument);
    CHECK_FALSE(isValidViewCount(16));
}

TEST_CASE("lod view directions: minimum pairwise angle and covering radius per set") {
    // Minimum spacing: icosahedron edge 63.43 deg, dodecahedron edge 41.81 deg, and the combined
    // set's closest pair is an icosahedron vertex and an adjacent face centre, 37.38 deg.
    CHECK(degrees(minPairwiseAngle(viewDirections(12))) == doctest::Approx(63.435).epsilon(1e-4));
    CHECK(degrees(minPairwiseAngle(viewDirections(20))) == doctest::Approx(41.810).epsilon(1e-4));
    CHECK(degrees(minPairwiseAngle(viewDirections(32))) == doctest::Approx(37.377).epsilon(1e-4));
    // Covering radius (the worst angle to the nearest view): 12 and 20 views both 37.38 deg
    // (the deepest hole of each set is the other solid's vertex, 37.38 deg from its nearest
    // views); 32 views 20.9 deg (measured: the circumcentre of a (vertex, vertex, face) triangle).
    // Fibonacci sampling approaches from below.
    const float c12 = degrees(coveringRadius(viewDirections(12))), c20 = degrees(coveringRadius(viewDirections(20))),
                c32 = degrees(coveringRadius(viewDirections(32)));
    MESSAGE("covering radius: 12 views ", c12, " deg, 20 views ", c20, " deg, 32 views ", c32, " deg");
    CHECK(c12 <= 37.38f);
    CHECK(c12 > 36.8f);
    CHECK(c20 <= 37.38f);
    CHECK(c20 > 36.8f);
    CHECK(c32 <= 22.70f);
    CHECK(c32 > 22.3f);
}

TEST_CASE("lod view directions: nearest views are sorted by angle") {
    const auto dirs = viewDirections(20);
    for (const auto& v : fibonacciSphere(200)) {
        const auto n = nearestViews(dirs, v * 3.0f, 5);
        REQUIRE(n.size() == 5);
        for (std::size_t i = 1; i < n.size(); ++i) CHECK(glm::dot(dirs[n[i - 1]], v) >= glm::dot(dirs[n[i]], v));
        CHECK(std::acos(std::min(1.0f, glm::dot(dirs[n[0]], v))) == doctest::Approx(angleToNearestView(dirs, v)).epsilon(1e-4));
    }
    // Exactly at a view: that view first, angle 0.
    CHECK(nearestViews(dirs, dirs[7], 1)[0] == 7);
    CHECK(angleToNearestView(dirs, dirs[7]) < 1e-3f);
    CHECK(nearestViews(dirs, dirs[0], 99).size() == 20);
}

TEST_CASE("lod view directions: hole-filling adjacency") {
    // Icosahedron: the 3 nearest views of any direction are a face's corners, so each vertex's
    // partners are exactly its 5 edge neighbours (63.43 deg away).
    const auto ico = viewDirections(12);
    const auto pairs = adjacentViews(ico);
    std::map<int, std::set<int>> partners;
    for (auto [v, w] : pairs) {
        CHECK(v != w);
        partners[v].insert(w);
        CHECK(degrees(std::acos(glm::dot(ico[v], ico[w]))) == doctest::Approx(63.435).epsilon(1e-3));
    }
    CHECK(partners.size() == 12);
    for (auto& [v, set] : partners) CHECK(set.size() == 5);
    CHECK(pairs.size() == 60);
    // Every set: every view has partners, and the relation is symmetric.
    for (int n : {20, 32}) {
        const auto p = adjacentViews(viewDirections(n));
        std::set<std::pair<int, int>> s(p.begin(), p.end());
        std::set<int> firsts;
        for (auto [v, w] : p) {
            firsts.insert(v);
            CHECK(s.count({w, v}) == 1);
        }
        CHECK(int(firsts.size()) == n);
        MESSAGE(n, " views: ", p.size(), " ordered adjacent pairs");
    }
}
