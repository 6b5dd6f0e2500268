// The wireframe scene option (scene/wireframe.hpp): three edge strips per triangle, each lying in
// its triangle's plane and inside it, `width` wide in world units under the object's transform;
// the builtin ":wireframe" suffix and the scene description's "wireframe" key.
#include "gltf_test_builder.hpp"

#include "scene/builtin_scenes.hpp"
#include "scene/mesh_builders.hpp"
#include "scene/scene_description.hpp"
#include "scene/wireframe.hpp"

#include <doctest/doctest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

using namespace strata;

namespace {

// Distance of world point p from the line through a and b.
double lineDistance(glm::dvec3 p, glm::dvec3 a, glm::dvec3 b) {
    return glm::length(glm::cross(p - a, glm::normalize(b - a)));
}

// Checks every strip of `wire` (built from `mesh` with `world` and `width`) against its triangle.
void checkStrips(const Mesh& mesh, const Mesh& wire, const glm::mat4& world, float width) {
    REQUIRE(wire.triangleCount() == 6 * mesh.triangleCount());
    REQUIRE(wire.positions.size() == 12 * mesh.triangleCount());
    auto toWorld = [&](glm::vec3 p) { return glm::dvec3(world * glm::vec4(p, 1.0f)); };
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const glm::vec3 v[3] = {mesh.positions[mesh.indices[3 * t]], mesh.positions[mesh.indices[3 * t + 1]],
                                mesh.positions[mesh.indices[3 * t + 2]]};
        const glm::dvec3 a(v[0]), b(v[1]), c(v[2]);
        const glm::dvec3 n = glm::normalize(glm::cross(b - a, c - a));
        const double size = std::max(glm::length(b - a), std::max(glm::length(c - b), glm::length(a - c)));
        for (int e = 0; e < 3; ++e) {
            const std::size_t base = 12 * t + 4 * std::size_t(e);
            for (std::size_t k = 0; k < 4; ++k) {
                const glm::dvec3 p(wire.positions[base + k]);
                // Coplanar with the triangle, to float round-off of the mesh's scale.
                CHECK(std::abs(glm::dot(n, p - a)) <= 1e-6 * size);
                // Inside the triangle: barycentric coordinates >= 0 (up to round-off).
                const double area = glm::dot(glm::cross(b - a, c - a), n);
                const double u = glm::dot(glm::cross(c - b, p - b), n) / area;
                const double w = glm::dot(glm::cross(a - c, p - c), n) / area;
                CHECK(u >= -1e-6);
                CHECK(w >= -1e-6);
                CHECK(1.0 - u - w >= -1e-6);
            }
            // The first two vertices are the edge itself, bit for bit (so they transform as the surface's).
            CHECK(wire.positions[base] == v[e]);
            CHECK(wire.positions[base + 1] == v[(e + 1) % 3]);
            // The inner side lies `width` from the edge in world units (unless capped at a third of
            // the triangle's height).
            const glm::dvec3 wa = toWorld(v[e]), wb = toWorld(v[(e + 1) % 3]), wc = toWorld(v[(e + 2) % 3]);
            const double height = lineDistance(wc, wa, wb);
            const double expected = std::min(double(width), height / 3.0);
            CHECK(lineDistance(toWorld(wire.positions[base + 2]), wa, wb) == doctest::Approx(expected).epsilon(1e-4));
            CHECK(lineDistance(toWorld(wire.positions[base + 3]), wa, wb) == doctest::Approx(expected).epsilon(1e-4));
        }
    }
}

}  // namespace

TEST_CASE("wireframe: three strips per triangle, in the triangle's plane, width in world units") {
    SUBCASE("a box, identity") {
        const Mesh box = makeBox({0, 0, 0}, {1, 2, 3});
        const Mesh wire = makeWireframeMesh(box, glm::mat4(1.0f), 0.05f);
        CHECK(wire.triangleCount() == 72);  // 12 triangles x 3 edges x 2
        checkStrips(box, wire, glm::mat4(1.0f), 0.05f);
    }
    SUBCASE("a sphere under a non-uniform scale and a rotation") {
        const Mesh sphere = makeSphere(1.0f, 12, 6);
        const glm::mat4 world = glm::rotate(glm::scale(glm::translate(glm::mat4(1.0f), {3, -1, -7}), {2.0f, 0.5f, 1.0f}),
                                            0.7f, glm::normalize(glm::vec3(1, 2, 3)));
        const Mesh wire = makeWireframeMesh(sphere, world, 0.02f);
        checkStrips(sphere, wire, world, 0.02f);
    }
    SUBCASE("thin triangles cap at a third of their height; degenerate ones draw nothing") {
        Mesh m;
        m.positions = {{0, 0, 0}, {10, 0, 0}, {5, 0.03f, 0}, {0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
        m.normals.assign(m.positions.size(), {0, 0, 1});
        m.indices = {0, 1, 2};
        const Mesh wire = makeWireframeMesh(m, glm::mat4(1.0f), 0.5f);
        checkStrips(m, wire, glm::mat4(1.0f), 0.5f);
        m.indices = {3, 4, 5};  // collinear
        CHECK(makeWireframeMesh(m, glm::mat4(1.0f), 0.5f).triangleCount() == 0);
    }
}

TEST_CASE("wireframe: added over every transparent object, first in object order, same placement") {
    Scene plain = makeBuiltinScene("cubes");
    Scene wired = makeBuiltinScene("cubes:wireframe");
    CHECK(wired.name == "cubes:wireframe");
    const auto before = flatten(plain), after = flatten(wired);
    // Three transparent cubes get a wireframe each; the opaque floor does not.
    REQUIRE(after.size() == before.size() + 3);
    for (std::size_t i = 0; i < 3; ++i) {
        const Object& wire = after[i];
        const Object& surface = after[3 + i];
        CHECK(wired.materials[std::size_t(wire.material)].name == "wireframe");
        CHECK(wired.materials[std::size_t(wire.material)].isTransparent());
        CHECK(wire.world == surface.world);
        CHECK(wired.meshes[std::size_t(wire.mesh)].triangleCount() ==
              6 * wired.meshes[std::size_t(surface.mesh)].triangleCount());
    }
    CHECK_THROWS_AS(makeBuiltinScene("wireframe"), std::invalid_argument);
    CHECK_THROWS_AS(makeBuiltinScene("cubes:wire"), std::invalid_argument);
}

TEST_CASE("wireframe: the scene description's \"wireframe\" key") {
    test::GltfBuilder b;
    int pos = b.positions(test::kQuadPositions);
    int idx = b.accessor(b.view(std::vector<std::uint8_t>{0, 1, 2, 0, 2, 3}), test::kUByte, 6, "SCALAR");
    b.meshNode(test::json::array({{{"attributes", {{"POSITION", pos}}}, {"indices", idx}}}));
    const auto model = b.writeGltf("wire-quad");
    const std::string object = R"({"model": ")" + model.string() + R"(", "material": {"alpha": 0.5}})";
    auto load = [&](const std::string& wireframe) {
        return parseSceneDescription(R"({"objects": [)" + object + "]" + wireframe + "}", test::tempDir() / "wire.json");
    };
    CHECK(flatten(load("")).size() == 1);
    CHECK(flatten(load(R"(, "wireframe": false)")).size() == 1);
    const Scene on = load(R"(, "wireframe": {"width": 0.01, "color": [1, 0, 0], "alpha": 0.8})");
    const auto objects = flatten(on);
    REQUIRE(objects.size() == 2);
    const Material& wire = on.materials[std::size_t(objects[0].material)];
    CHECK(wire.alpha == doctest::Approx(0.8f));
    CHECK(wire.baseColor == glm::vec3(1, 0, 0));
    CHECK(on.meshes[std::size_t(objects[0].mesh)].triangleCount() == 12);
    CHECK_THROWS_AS(load(R"(, "wireframe": {"width": 0})"), LoadError);
    CHECK_THROWS_AS(load(R"(, "wireframe": {"colour": [1, 0, 0]})"), LoadError);
    CHECK_THROWS_AS(load(R"(, "wireframe": 3)"), LoadError);
}
