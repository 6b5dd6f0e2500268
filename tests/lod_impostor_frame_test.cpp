// The back-perspective frame of one impostor view (lod/impostor_frame.hpp): the sphere maps
// into the unit cube, the inverse round-trips, slice planes sit at uniform distances.
#include "lod/impostor_frame.hpp"
#include "lod/view_directions.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace strata::lod;

TEST_CASE("lod impostor frame: apex behind the object, frustum just encloses the sphere") {
    const glm::vec3 c(1.0f, -2.0f, 0.5f);
    const float r = 2.0f;
    const ImpostorFrame f = makeImpostorFrame(c, r, glm::vec3(0.0f, 0.0f, 2.0f));
    CHECK(f.axis.z == doctest::Approx(1.0f));
    CHECK(glm::length(f.apex - (c - glm::vec3(0, 0, 3.0f * r))) < 1e-5f);
    CHECK(f.slabNear() == doctest::Approx(2.0f * r));
    CHECK(f.slabFar() == doctest::Approx(4.0f * r));
    CHECK(std::abs(glm::dot(f.right, f.axis)) < 1e-6f);
    CHECK(std::abs(glm::dot(f.up, f.axis)) < 1e-6f);
    CHECK(glm::dot(glm::cross(f.right, f.up), -f.axis) == doctest::Approx(1.0f));  // right-handed camera
    // sin(half-angle) = r / D: the cone from the apex is tangent to the sphere.
    CHECK(std::atan(f.tanHalf) == doctest::Approx(std::asin(1.0f / 3.0f)));
}

TEST_CASE("lod impostor frame: points on the sphere map into [0,1]^3 and round-trip") {
    const glm::vec3 c(10.0f, 3.0f, -7.0f);
    for (float r : {0.01f, 1.0f, 1.0e5f})
        for (const auto& v : viewDirections(20)) {
            const ImpostorFrame f = makeImpostorFrame(c * (r > 1e4f ? 1e4f : 1.0f), r, v);
            for (const auto& s : fibonacciSphere(300)) {
                const glm::vec3 p = f.centre + s * r;
                const glm::vec3 uvt = f.toUvt(p);
                for (int k = 0; k < 3; ++k) {
                    CHECK(uvt[k] >= -1e-4f);
                    CHECK(uvt[k] <= 1.0f + 1e-4f);
                }
                CHECK(glm::length(f.fromUvt(uvt) - p) <= 1e-4f * r + 1e-6f * glm::length(f.centre));  // float round-off of |c|
            }
            // Centre: middle of the image, middle of the slab. The sphere's point nearest the
            // apex has t = 0, the farthest t = 1.
            const glm::vec3 mid = f.toUvt(f.centre);
            CHECK(glm::length(mid - glm::vec3(0.5f)) < 1e-4f);
            CHECK(f.toUvt(f.centre - v * r).z == doctest::Approx(0.0f).epsilon(1e-4));
            CHECK(f.toUvt(f.centre + v * r).z == doctest::Approx(1.0f).epsilon(1e-4));
        }
}

TEST_CASE("lod impostor frame: slice planes and quads") {
    const ImpostorFrame f = makeImpostorFrame(glm::vec3(0.0f), 1.0f, glm::vec3(1, 1, 0));
    const int L = 8;
    for (int s = 0; s < L; ++s) {
        // Uniform steps of the distance from the apex over [D - r, D + r], at interval middles.
        CHECK(f.sliceDistance(s, L) == doctest::Approx(2.0f + 2.0f * (s + 0.5f) / L));
        const auto q = f.sliceQuad(s, L);
        for (const auto& p : q) {
            CHECK(glm::dot(p - f.apex, f.axis) == doctest::Approx(f.sliceDistance(s, L)));
            CHECK(f.toUvt(p).z == doctest::Approx((s + 0.5f) / L));
        }
        // Full quad: corners at u, v in {0, 1}; the cross-section grows linearly with distance.
        CHECK(glm::length(q[1] - q[0]) == doctest::Approx(2.0f * f.sliceDistance(s, L) * f.tanHalf));
        CHECK(glm::length(f.toUvt(q[2]) - glm::vec3(1.0f, 1.0f, (s + 0.5f) / L)) < 1e-5f);
        // Corners counter-clockwise seen from the apex.
        CHECK(glm::dot(glm::cross(q[1] - q[0], q[2] - q[0]), f.axis) < 0.0f);
        // A texel rectangle restricts the quad to its (u, v) range.
        const auto r = f.sliceQuad(s, L, UvRect{{0.25f, 0.5f}, {0.75f, 0.625f}});
        CHECK(glm::length(f.toUvt(r[0]) - glm::vec3(0.25f, 0.5f, (s + 0.5f) / L)) < 1e-5f);
        CHECK(glm::length(f.toUvt(r[2]) - glm::vec3(0.75f, 0.625f, (s + 0.5f) / L)) < 1e-5f);
    }
    // L = 1: one plane through the centre.
    CHECK(f.sliceDistance(0, 1) == doctest::Approx(3.0f));
}

TEST_CASE("lod impostor frame: the bake camera maps (u, v) to the image and the slab to depth [0, 1]") {
    const ImpostorFrame f = makeImpostorFrame(glm::vec3(0.5f, 0.0f, 0.0f), 2.0f, glm::vec3(0.3f, -1.0f, 0.2f));
    const glm::mat4 vp = f.projection() * f.view();
    for (const auto& s : fibonacciSphere(100)) {
        const glm::vec3 p = f.centre + s * 1.7f;
        const glm::vec4 clip = vp * glm::vec4(p, 1.0f);
        const glm::vec3 ndc = glm::vec3(clip) / clip.w;
        const glm::vec3 uvt = f.toUvt(p);
        CHECK(ndc.x * 0.5f + 0.5f == doctest::Approx(uvt.x).epsilon(1e-4));
        CHECK(ndc.y * 0.5f + 0.5f == doctest::Approx(uvt.y).epsilon(1e-4));
        CHECK(ndc.z > 0.0f);
        CHECK(ndc.z < 1.0f);
    }
    // Depth grows away from the apex: the farthest surface has the largest depth.
    auto depth = [&](const glm::vec3& p) { const glm::vec4 c = vp * glm::vec4(p, 1.0f); return c.z / c.w; };
    CHECK(depth(f.centre + f.axis) > depth(f.centre));
}
