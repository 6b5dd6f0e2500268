// builtin:field:N[:transparent] (scene/builtin_scenes.hpp): the impostor LOD bench's scene.
#include "scene/builtin_scenes.hpp"
#include "scene/mesh_builders.hpp"
#include "scene/mesh_volume.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <set>
#include <stdexcept>

using namespace strata;

TEST_CASE("field: the dense blob is closed, welded, 20 n^2 triangles") {
    const Mesh blob = makeBumpyBlob(kFieldMeshSegments);
    CHECK(blob.triangleCount() == 46080);
    CHECK(kFieldMeshTriangles == 46080);
    // An icosphere split n ways per edge has 10 n^2 + 2 vertices once every shared one is welded.
    CHECK(blob.positions.size() == 10 * 48 * 48 + 2);
    CHECK(blob.normals.size() == blob.positions.size());
    const MeshVolume volume = analyzeMeshVolume(blob);
    CHECK(volume.closed);
    CHECK(volume.frontFacesOutward);
    // The ellipsoid stretch and bumps: extents 2 x 1.7 x 1.5 within the bumps' +-14 %.
    const Bounds b = blob.bounds();
    const glm::vec3 extent = b.max - b.min, nominal(2.0f, 1.7f, 1.5f);
    for (int k = 0; k < 3; ++k) {
        CHECK(extent[k] > 0.86f * nominal[k]);
        CHECK(extent[k] < 1.14f * nominal[k]);
    }
    // Not a scaled sphere: the stretch shows.
    CHECK(extent.x > 1.15f * extent.z);
    CHECK(makeBumpyBlob(1).triangleCount() == 20);
    CHECK(makeBumpyBlob(1).positions.size() == 12);
    CHECK_THROWS_AS(makeBumpyBlob(0), std::invalid_argument);
    CHECK_THROWS_AS(makeBumpyBlob(257), std::invalid_argument);
}

TEST_CASE("field: N instances of one mesh on an opaque ground") {
    const Scene s = makeBuiltinScene("field:10");
    const std::vector<Object> objects = flatten(s);
    REQUIRE(objects.size() == 11);
    std::set<int> meshes;
    std::set<std::pair<float, float>> orientations;
    for (int i = 0; i < 10; ++i) {
        meshes.insert(objects[std::size_t(i)].mesh);
        CHECK_FALSE(s.materials[std::size_t(objects[std::size_t(i)].material)].isTransparent());
        orientations.insert({objects[std::size_t(i)].world[0][0], objects[std::size_t(i)].world[0][2]});
    }
    CHECK(meshes.size() == 1);  // all instances share one mesh
    CHECK(s.meshes[std::size_t(*meshes.begin())].triangleCount() == 46080);
    CHECK(orientations.size() == 10);  // every instance turned differently
    const Object& ground = objects.back();
    CHECK(meshes.count(ground.mesh) == 0);
    CHECK_FALSE(s.materials[std::size_t(ground.material)].isTransparent());
    CHECK_FALSE(hasTransparency(s, objects));
    REQUIRE(s.camera.has_value());
    // The camera is above the ground and outside every instance's bounds.
    CHECK(s.camera->position.y > 2.0f);
    for (int i = 0; i < 10; ++i) {
        const Bounds& b = objects[std::size_t(i)].worldBounds;
        CHECK(glm::length(s.camera->position - b.center()) > 2.0f * b.radius());
    }
    // Triangles in all: 10 x 46080 + the ground box's 12.
    std::size_t triangles = 0;
    for (const auto& o : objects) triangles += s.meshes[std::size_t(o.mesh)].triangleCount();
    CHECK(triangles == 10 * 46080 + 12);
}

TEST_CASE("field: transparent variant, default and limits") {
    const Scene t = makeBuiltinScene("field:4:transparent");
    const auto objects = flatten(t);
    REQUIRE(objects.size() == 5);
    for (int i = 0; i < 4; ++i) {
        const Material& m = t.materials[std::size_t(objects[std::size_t(i)].material)];
        CHECK(m.isTransparent());
        CHECK(m.alpha == 0.5f);
    }
    CHECK_FALSE(t.materials[std::size_t(objects.back().material)].isTransparent());
    CHECK(t.name == "field:4:transparent");
    CHECK(flatten(makeBuiltinScene("field")).size() == 101);
    CHECK(flatten(makeBuiltinScene("field:1")).size() == 2);
    CHECK(flatten(makeBuiltinScene("field:1000")).size() == 1001);
    for (const char* bad : {"field:0", "field:1001", "field:x", "field:10:glass", "field:-3"}) {
        CAPTURE(bad);
        CHECK_THROWS_AS(makeBuiltinScene(bad), std::invalid_argument);
    }
    CHECK_THROWS_WITH(makeBuiltinScene("field:1001"), "builtin:field:1001: argument '1001' must be an integer in [1, 1000]");
}

TEST_CASE("field:1: the instance's bounding sphere spans about half the image height") {
    // scripts/bench_lod.sh's crossover sweep turns image size into on-screen size with this.
    const Scene s = makeBuiltinScene("field:1");
    const auto objects = flatten(s);
    const Bounds& b = objects.front().worldBounds;
    REQUIRE(s.camera.has_value());
    const double d = glm::length(s.camera->position - b.center()), r = b.radius();
    const double f = 1.0 / (2.0 * std::tan(glm::radians(double(s.camera->fovYDegrees)) * 0.5));
    const double fraction = 2.0 * f * r / std::sqrt(d * d - r * r);
    MESSAGE("field:1 instance: bounding diameter " << fraction << " x image height");
    CHECK(fraction > 0.590);
    CHECK(fraction < 0.593);
}
