#pragma once
// Small scenes for the material tests (material_texture_gl_test.cpp, material_pbr_gl_test.cpp):
// a camera that sees exactly [-1, 1]^2 at z = 0 over a grey backdrop, quads with TEXCOORD_0
// across them, two-texel images, and the techniques that are exact given enough memory.
#include "gl_test_support.hpp"

#include <doctest/doctest.h>

#include "reference/raycast.hpp"
#include "render/shading.hpp"
#include "scene/mesh_builders.hpp"
#include "scene/tangents.hpp"

#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace strata::test::material {


inline constexpr float kTolerance = 2.0f / 255.0f;
inline const glm::ivec2 kSize(16, 16);

// Two texels, left and right, sRGB-encoded colour and linear alpha.
inline TextureImage twoTexels(glm::u8vec4 left, glm::u8vec4 right) {
    TextureImage image;
    image.name = "two texels";
    image.width = 2;
    image.height = 1;
    image.rgba = {left.r, left.g, left.b, left.a, right.r, right.g, right.b, right.a};
    return image;
}

// What the sampler returns for an 8-bit texel: colour decoded from sRGB, alpha as is.
inline glm::vec4 linearTexel(glm::u8vec4 t) {
    return {srgbToLinear(t.r / 255.0f), srgbToLinear(t.g / 255.0f), srgbToLinear(t.b / 255.0f), t.a / 255.0f};
}

inline Sampler nearestSampler(TextureWrap wrap = TextureWrap::ClampToEdge) {
    Sampler s;
    s.magFilter = TextureFilter::Nearest;
    s.minFilter = TextureFilter::Nearest;
    s.wrapS = s.wrapT = wrap;
    return s;
}

// A quad in the plane z = `z` spanning x in [x0, x1], y in [-1, 1], with TEXCOORD_0 mapping
// x = -1 to u = 0 and x = 1 to u = 1 (v = 0 at the top, as glTF's image origin).
inline Mesh quad(float x0, float x1, float z) {
    Mesh m;
    m.name = "quad";
    m.positions = {{x0, -1, z}, {x1, -1, z}, {x1, 1, z}, {x0, 1, z}};
    m.normals.assign(4, {0, 0, 1});
    m.indices = {0, 1, 2, 0, 2, 3};
    for (const auto& p : m.positions) m.texCoords[0].push_back({(p.x + 1.0f) * 0.5f, (1.0f - p.y) * 0.5f});
    return m;
}

// An empty scene whose camera sees exactly [-1, 1]^2 at z = 0, over an opaque grey backdrop.
inline Scene framedScene() {
    Scene s;
    s.name = "material pair";
    s.materials.push_back(Material{});
    CameraPose pose;
    pose.position = {0.0f, 0.0f, 3.0f};
    pose.fovYDegrees = float(2.0 * std::atan(1.0 / 3.0) * 180.0 / 3.14159265358979323846);
    s.camera = pose;
    Material backdrop;
    backdrop.name = "backdrop";
    backdrop.baseColor = {0.2f, 0.3f, 0.4f};
    int m = s.addMaterial(backdrop);
    Mesh back = makeQuad(4.0f, 4.0f);
    for (auto& p : back.positions) p.z = -1.0f;
    back.material = m;
    Node n;
    n.meshes = {s.addMesh(back)};
    s.addNode(n);  // a root: addNode lists it
    return s;
}

inline void addObject(Scene& s, Mesh mesh, const Material& material) {
    mesh.material = s.addMaterial(material);
    Node n;
    n.meshes = {s.addMesh(std::move(mesh))};
    s.addNode(n);  // a root: addNode lists it
}

inline Material blend(glm::vec4 factor) {
    Material m;
    m.baseColor = glm::vec3(factor);
    m.alpha = factor.a;
    m.alphaMode = AlphaMode::Blend;
    return m;
}

// The techniques that are exact given enough memory (as exact_techniques_gl_test.cpp): the
// robust ones, and the bounded ones given a capacity that holds every fragment.
inline std::vector<std::string> exactIds() {
    std::vector<std::string> ids;
    for (const auto& e : techniqueRegistry())
        if (e.info.robust || test::hasSetting(e.info.id, "capacity")) ids.push_back(e.info.id);
    return ids;
}

inline std::unique_ptr<Technique> exactTechnique(const std::string& id, int capacity = 4) {
    auto t = createTechnique(id);
    if (test::hasSetting(id, "capacity")) test::setSetting(*t, "capacity=" + std::to_string(capacity));
    return t;
}

// Renders `scene` with every exact technique that `which` accepts (all when empty), a bounded
// one at `capacity`, and checks each against the CPU reference within kTolerance with nothing
// overflowed; returns the reference image.
inline Image checkAgainstReference(Scene scene, const std::function<bool(const TechniqueInfo&)>& which = {},
                                   int capacity = 4) {
    test::glContext();
    deriveMissingTangents(scene);
    const std::vector<Object> objects = flatten(scene);
    const Camera camera = defaultCamera(scene, objects);
    const Image cpu = raycastReference(scene, objects, camera, kSize.x, kSize.y);
    GpuScene gpu(std::move(scene));
    for (const std::string& id : exactIds()) {
        auto t = exactTechnique(id, capacity);
        if (which && !which(t->info())) continue;
        CAPTURE(id);
        test::Rendered r = test::renderWith(gpu, camera, kSize, *t);
        CHECK(compareImages(r.image, cpu).maxAbsError <= kTolerance);
        CHECK_FALSE(r.result.stats.overflowed);
    }
    return cpu;
}

}  // namespace strata::test::material
