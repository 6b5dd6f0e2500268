// Which meshes bound a volume (closed, consistently oriented after welding), which way they
// face, and whether a point is inside (the winding number), on meshes whose answer is known.
#include "scene/mesh_builders.hpp"
#include "scene/mesh_volume.hpp"

#include <doctest/doctest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>

using namespace strata;

TEST_CASE("boxes and spheres are closed volumes facing out; a quad and an open box are not") {
    const MeshVolume box = analyzeMeshVolume(makeBox({0, 0, 0}, {1, 2, 3}));
    CHECK(box.closed);
    CHECK(box.frontFacesOutward);
    CHECK(box.signedVolume == doctest::Approx(6.0));
    // The sphere's seam and pole vertices are duplicated and differ by round-off: welded.
    const MeshVolume sphere = analyzeMeshVolume(makeSphere(1.0f, 48, 24));
    CHECK(sphere.closed);
    CHECK(sphere.frontFacesOutward);
    CHECK(sphere.signedVolume == doctest::Approx(4.18879).epsilon(0.01));

    const MeshVolume quad = analyzeMeshVolume(makeQuad(1.0f, 1.0f));
    CHECK_FALSE(quad.closed);
    CHECK_FALSE(quad.reason.empty());

    Mesh open = makeBox({0, 0, 0}, {1, 1, 1});
    open.indices.resize(open.indices.size() - 6);  // one face (two triangles) removed
    const MeshVolume o = analyzeMeshVolume(open);
    CHECK_FALSE(o.closed);
    CHECK(o.openEdges == 4);
    CHECK(o.reason == "4 open edges");
}

TEST_CASE("an inside-out box is closed and entered through its back faces") {
    Mesh box = makeBox({0, 0, 0}, {1, 1, 1});
    for (std::size_t t = 0; t < box.indices.size(); t += 3) std::swap(box.indices[t + 1], box.indices[t + 2]);
    const MeshVolume v = analyzeMeshVolume(box);
    CHECK(v.closed);
    CHECK_FALSE(v.frontFacesOutward);
    CHECK(v.signedVolume == doctest::Approx(-1.0));
}

TEST_CASE("a mesh with one triangle flipped is not consistently oriented") {
    Mesh box = makeBox({0, 0, 0}, {1, 1, 1});
    std::swap(box.indices[1], box.indices[2]);
    const MeshVolume v = analyzeMeshVolume(box);
    CHECK_FALSE(v.closed);
    CHECK(v.badEdges > 0);
}

TEST_CASE("the winding number is 1 inside, 0 outside, either orientation; containsPoint applies the transform") {
    // The sphere's seam vertices differ by float round-off (about 1e-7), so the mesh has
    // slivers of gap and the winding number is 1 or 0 to about 1e-7, not to double precision.
    const Mesh sphere = makeSphere(1.0f, 32, 16);
    CHECK(windingNumber(sphere, glm::dvec3(0.0)) == doctest::Approx(1.0).epsilon(1e-6));
    CHECK(windingNumber(sphere, glm::dvec3(0.3, -0.5, 0.2)) == doctest::Approx(1.0).epsilon(1e-6));
    CHECK(std::abs(windingNumber(sphere, glm::dvec3(1.5, 0.0, 0.0))) < 1e-6);
    const Mesh box = makeBox({-1, -1, -1}, {1, 1, 1});  // exact corners: exact to double round-off
    CHECK(windingNumber(box, glm::dvec3(0.2, 0.1, -0.3)) == doctest::Approx(1.0).epsilon(1e-12));
    CHECK(std::abs(windingNumber(box, glm::dvec3(3.0, 0.1, -0.3))) < 1e-12);
    const glm::mat4 world = glm::translate(glm::mat4(1.0f), {5, 0, 0}) * glm::scale(glm::mat4(1.0f), glm::vec3(-2, 2, 2));
    CHECK(containsPoint(sphere, world, {5.0f, 1.9f, 0.0f}));
    CHECK_FALSE(containsPoint(sphere, world, {5.0f, 2.1f, 0.0f}));
    CHECK_FALSE(containsPoint(sphere, world, {0.0f, 0.0f, 0.0f}));
}

TEST_CASE("classifyVolumes: a volume needs a transparent volume material and a closed mesh") {
    Scene s;
    s.materials.push_back(Material{});
    Material glass;
    glass.alphaMode = AlphaMode::Blend;
    glass.alpha = 0.5f;
    Material medium = glass;
    medium.volume = true;
    medium.tau = glm::vec3(1.0f);
    const int glassId = s.addMaterial(glass), mediumId = s.addMaterial(medium);
    const int sphere = s.addMesh(makeSphere(1.0f, 16, 8)), quad = s.addMesh(makeQuad(1, 1));
    auto place = [&](int mesh, int material) {
        Node n;
        n.meshes = {mesh};
        n.materialOverride = material;
        s.addNode(n);
    };
    place(sphere, mediumId);
    place(sphere, glassId);
    place(quad, mediumId);
    place(sphere, 0);
    const auto objects = flatten(s);
    const auto kinds = classifyVolumes(s, objects);
    REQUIRE(kinds.size() == 4);
    CHECK(kinds[0].volume);
    CHECK(kinds[0].status == "volume");
    CHECK_FALSE(kinds[1].volume);
    CHECK(kinds[1].status.find("declares no volume") != std::string::npos);
    CHECK_FALSE(kinds[2].volume);
    CHECK(kinds[2].status.find("not closed") != std::string::npos);
    CHECK_FALSE(kinds[3].volume);
    CHECK(kinds[3].status == "opaque");
}
