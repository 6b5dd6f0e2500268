// The culling hierarchy (render/cull_hierarchy.hpp) answers exactly as the per-object sphere test
// (Frustum::mayContain) for every object, over grids of multi-part units and random views, while
// testing far fewer spheres than there are objects when the view holds a small part of the scene.
#include "render/cull_hierarchy.hpp"

#include <doctest/doctest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <random>

using namespace strata;

namespace {

// `side` x `side` units of three parts (a unit box and two smaller ones above it), 4 apart.
std::vector<Object> grid(int side) {
    std::vector<Object> objects;
    int unit = 0;
    for (int z = 0; z < side; ++z)
        for (int x = 0; x < side; ++x, ++unit)
            for (int part = 0; part < 3; ++part) {
                Object o;
                o.id = int(objects.size());
                o.unit = unit;
                const glm::vec3 at(4.0f * float(x), 1.2f * float(part), -4.0f * float(z));
                const float half = part == 0 ? 0.5f : 0.3f;
                o.worldBounds.extend(at - glm::vec3(half));
                o.worldBounds.extend(at + glm::vec3(half));
                objects.push_back(o);
            }
    return objects;
}

glm::mat4 viewProjection(glm::vec3 eye, glm::vec3 target, float fovDegrees) {
    return glm::perspectiveRH_ZO(glm::radians(fovDegrees), 1.5f, 0.1f, 5000.0f) * glm::lookAtRH(eye, target, {0, 1, 0});
}

}  // namespace

TEST_CASE("cull hierarchy: the same answer as the per-object test, for random views over a grid of units") {
    const std::vector<Object> objects = grid(30);  // 900 units, 2700 objects
    const CullHierarchy hierarchy(objects);
    CHECK(hierarchy.unitCount() == 900);
    std::mt19937 random(7);
    std::uniform_real_distribution<float> across(-20.0f, 140.0f), height(0.5f, 60.0f), fov(5.0f, 100.0f);
    std::vector<char> visible;
    for (int view = 0; view < 200; ++view) {
        const glm::vec3 eye(across(random), height(random), -across(random));
        const glm::vec3 target(across(random), 0.0f, -across(random));
        if (glm::length(target - eye) < 1.0f) continue;
        const Frustum frustum(viewProjection(eye, target, fov(random)));
        const CullCounts counts = hierarchy.cull(frustum, visible);
        REQUIRE(visible.size() == objects.size());
        std::size_t culled = 0, mismatches = 0;
        for (std::size_t i = 0; i < objects.size(); ++i) {
            const bool expected = frustum.mayContain(objects[i].worldBounds);
            mismatches += (bool(visible[i]) != expected) ? 1 : 0;
            culled += expected ? 0 : 1;
        }
        CAPTURE(view);
        CHECK(mismatches == 0);
        CHECK(counts.objectsCulled == culled);
    }
}

TEST_CASE("cull hierarchy: a narrow view over a large grid tests few spheres; units culled whole") {
    const std::vector<Object> objects = grid(100);  // 10^4 units, 3 x 10^4 objects
    const CullHierarchy hierarchy(objects);
    std::vector<char> visible;
    // Looking down at the corner unit (0, 0) from just above it: only units near it are in view.
    const Frustum frustum(viewProjection({0.0f, 12.0f, 0.5f}, {0.0f, 0.0f, 0.0f}, 20.0f));
    const CullCounts counts = hierarchy.cull(frustum, visible);
    CHECK(visible[0] == 1);
    CHECK(counts.unitsCulled > 9990);
    CHECK(counts.objectsCulled > 3 * 9990);
    CHECK(counts.objectsCulled <= 3 * counts.unitsCulled + 3 * 10);
    MESSAGE("spheres tested: " << counts.spheresTested << " for " << objects.size() << " objects");
    CHECK(counts.spheresTested < 200);
    // The whole grid in view (from far above): everything kept, nothing tested below the root's
    // children that lie wholly inside.
    const Frustum all(viewProjection({198.0f, 600.0f, 100.0f}, {198.0f, 0.0f, -198.0f}, 60.0f));
    const CullCounts none = hierarchy.cull(all, visible);
    CHECK(none.objectsCulled == 0);
    CHECK(none.unitsCulled == 0);
    CHECK(none.spheresTested < 100);
}

TEST_CASE("cull hierarchy: empty bounds are culled as the per-object test culls them; no objects, no work") {
    std::vector<Object> objects = grid(2);
    objects[4].worldBounds = Bounds{};  // a part with no geometry
    const CullHierarchy hierarchy(objects);
    std::vector<char> visible;
    const Frustum frustum(viewProjection({4.0f, 20.0f, 10.0f}, {2.0f, 0.0f, -2.0f}, 90.0f));
    hierarchy.cull(frustum, visible);
    CHECK(visible[4] == 0);
    CHECK(visible[3] == 1);
    const CullHierarchy empty(std::vector<Object>{});
    CHECK(empty.cull(frustum, visible).spheresTested == 0);
    CHECK(visible.empty());
}
