// Small equivalents of the Khronos glTF sample assets that define what a renderer must do with
// materials (AlphaBlendModeTest, VertexColorTest, TextureSettingsTest), written as glTF files
// by the tests' own writer (gltf_test_builder.hpp), loaded by the loader (which must warn about
// nothing in them), and drawn by every exact technique against the CPU reference and against
// values stated per pixel. The materials are unlit (KHR_materials_unlit: the colour is the base
// colour), so each expected value is the texel or vertex colour itself, composited by its
// alpha mode over the unlit backdrop; the 16 x 16 view sees exactly [-1, 1]^2 at z = 0.
#include "gltf_test_builder.hpp"
#include "material_test_scenes.hpp"

#include "reference/raycast.hpp"
#include "scene/gltf_loader.hpp"

#include <doctest/doctest.h>

#include <functional>

using namespace strata;
using namespace strata::test;
using namespace strata::test::material;

namespace {

const glm::vec3 kBackdrop(0.25f, 0.5f, 0.75f);

// A builder holding the unlit backdrop quad at z = -1 (material 0) and the extension list.
GltfBuilder unlitDocument() {
    GltfBuilder b;
    b.doc["extensionsUsed"] = {"KHR_materials_unlit"};
    b.material({{"name", "backdrop"},
                {"pbrMetallicRoughness", {{"baseColorFactor", {kBackdrop.r, kBackdrop.g, kBackdrop.b, 1.0}}}},
                {"extensions", {{"KHR_materials_unlit", json::object()}}}});
    const std::vector<float> back = {-4, -4, -1, 4, -4, -1, 4, 4, -1, -4, -4, -1, 4, 4, -1, -4, 4, -1};
    b.meshNode(json::array({{{"attributes", {{"POSITION", b.positions(back)}}}, {"material", 0}}}));
    return b;
}

// A quad in z = `z` spanning x in [x0, x1], y in [y0, y1] as two non-indexed triangles; its
// TEXCOORD_0 maps x in [-1, 1] to u in [u0, u1] and y = 1 to v = 0 (glTF's top row).
json quadPrimitive(GltfBuilder& b, float x0, float x1, float y0, float y1, float z, int material, float u0 = 0.0f,
                   float u1 = 1.0f, json extraAttributes = json::object()) {
    const std::vector<glm::vec2> corners = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y0}, {x1, y1}, {x0, y1}};
    std::vector<float> xyz, uv;
    for (const glm::vec2& c : corners) {
        xyz.insert(xyz.end(), {c.x, c.y, z});
        uv.insert(uv.end(), {u0 + (c.x + 1.0f) * 0.5f * (u1 - u0), (1.0f - c.y) * 0.5f});
    }
    json attributes = {{"POSITION", b.positions(xyz)}, {"TEXCOORD_0", b.accessor(b.view(uv), kFloat, 6, "VEC2")}};
    for (auto& [key, value] : extraAttributes.items()) attributes[key] = value;
    return {{"attributes", attributes}, {"material", material}};
}

json unlitMaterial(const json& pbr, const json& more = json::object()) {
    json m = {{"pbrMetallicRoughness", pbr}, {"extensions", {{"KHR_materials_unlit", json::object()}}}};
    for (auto& [key, value] : more.items()) m[key] = value;
    return m;
}

// The scene from `file`, framed like material_test_scenes.hpp's, loaded without a warning.
Scene loadFramed(const std::filesystem::path& file) {
    GltfLoadReport report;
    Scene s = loadGltf(file, report);
    CHECK(report.warnings.empty());
    for (const std::string& w : report.warnings) MESSAGE(w);
    s.camera = framedScene().camera;
    return s;
}

// Where pixel (x, y)'s ray meets z = 0.
glm::vec2 planeHit(const Camera& camera, int x, int y) {
    glm::dvec3 origin, direction;
    pixelRay(camera, kSize.x, kSize.y, x, y, origin, direction);
    const double t = -origin.z / direction.z;
    return glm::vec2(origin + t * direction);
}

// Renders `scene` with every exact technique and the CPU reference; each image must match
// `expected(hit)` (nullopt: a pixel too near an edge to state) within 2/255.
void checkStated(Scene scene, const std::function<std::optional<glm::vec3>(glm::vec2)>& expected) {
    test::glContext();
    const std::vector<Object> objects = flatten(scene);
    const Camera camera = defaultCamera(scene, objects);
    std::vector<std::pair<std::string, Image>> images;
    images.push_back({"cpu reference", raycastReference(scene, objects, camera, kSize.x, kSize.y)});
    GpuScene gpu(std::move(scene));
    for (const std::string& id : exactIds()) {
        auto t = exactTechnique(id);
        images.push_back({id, test::renderWith(gpu, camera, kSize, *t).image});
    }
    int stated = 0;
    for (int y = 0; y < kSize.y; ++y)
        for (int x = 0; x < kSize.x; ++x) {
            const std::optional<glm::vec3> want = expected(planeHit(camera, x, y));
            if (!want) continue;
            ++stated;
            for (const auto& [id, image] : images) {
                CAPTURE(id);
                CAPTURE(x);
                CAPTURE(y);
                const glm::vec4 got = image.at(x, y);
                CHECK(std::abs(got.r - want->r) <= kTolerance);
                CHECK(std::abs(got.g - want->g) <= kTolerance);
                CHECK(std::abs(got.b - want->b) <= kTolerance);
            }
        }
    CHECK(stated >= kSize.x * kSize.y / 2);
}

// Whether `v` lies within `margin` of any of `edges` (a pixel there may go either way).
bool nearAny(float v, std::initializer_list<float> edges, float margin = 0.07f) {
    for (float e : edges)
        if (std::abs(v - e) < margin) return true;
    return false;
}

}  // namespace

TEST_CASE("AlphaBlendModeTest, small: OPAQUE ignores alpha, MASK cuts at its cutoff, BLEND composites") {
    // Four texels of one colour with alphas 0.2, 0.4, 0.6, 0.8, left to right; three bands of
    // quads reading them: OPAQUE (bottom), MASK with cutoff 0.5 (middle), BLEND (top).
    const std::uint8_t alphas[4] = {51, 102, 153, 204};
    std::vector<std::uint8_t> texels;
    for (std::uint8_t a : alphas) texels.insert(texels.end(), {230, 120, 40, a});
    GltfBuilder b = unlitDocument();
    b.imageDataUri(encodeImage("alpha-steps.png", 4, 1, 4, OIIO::TypeDesc::UINT8, texels.data()));
    b.doc["samplers"] = {{{"magFilter", 9728}, {"minFilter", 9728}, {"wrapS", 33071}, {"wrapT", 33071}}};
    b.doc["textures"] = {{{"source", 0}, {"sampler", 0}}};
    const json texture = {{"baseColorTexture", {{"index", 0}}}};
    b.material(unlitMaterial(texture, {{"alphaMode", "OPAQUE"}}));
    b.material(unlitMaterial(texture, {{"alphaMode", "MASK"}, {"alphaCutoff", 0.5}}));
    b.material(unlitMaterial(texture, {{"alphaMode", "BLEND"}}));
    b.meshNode(json::array({quadPrimitive(b, -1, 1, -1, -1.0f / 3.0f, 0, 1), quadPrimitive(b, -1, 1, -1.0f / 3.0f, 1.0f / 3.0f, 0, 2),
                            quadPrimitive(b, -1, 1, 1.0f / 3.0f, 1, 0, 3)}));
    Scene s = loadFramed(b.writeGltf("alpha-blend-modes"));

    const glm::vec3 colour(srgbToLinear(230 / 255.0f), srgbToLinear(120 / 255.0f), srgbToLinear(40 / 255.0f));
    checkStated(std::move(s), [&](glm::vec2 p) -> std::optional<glm::vec3> {
        if (nearAny(p.x, {-0.5f, 0.0f, 0.5f}) || nearAny(p.y, {-1.0f / 3.0f, 1.0f / 3.0f})) return std::nullopt;
        const int texel = std::clamp(int((p.x + 1.0f) * 2.0f), 0, 3);
        const float alpha = alphas[texel] / 255.0f;
        if (p.y < -1.0f / 3.0f) return colour;                        // OPAQUE
        if (p.y < 1.0f / 3.0f) return alpha >= 0.5f ? colour : kBackdrop;  // MASK
        return colour * alpha + kBackdrop * (1.0f - alpha);           // BLEND
    });
}

TEST_CASE("VertexColorTest, small: COLOR_0 as float VEC3, normalized byte VEC4 and normalized short VEC4 agree") {
    // (0.2, 0.4, 0.6) in each encoding, exactly representable in all three (51/255, 13107/65535);
    // the two VEC4 bands carry alpha 0.4 on a BLEND material, the VEC3 band none (alpha 1).
    GltfBuilder b = unlitDocument();
    b.material(unlitMaterial(json::object(), {{"alphaMode", "BLEND"}}));
    std::vector<float> floats;
    for (int i = 0; i < 6; ++i) floats.insert(floats.end(), {0.2f, 0.4f, 0.6f});
    const int asFloat = b.accessor(b.view(floats), kFloat, 6, "VEC3");
    std::vector<std::uint8_t> bytes;
    std::vector<std::uint16_t> shorts;
    for (int i = 0; i < 6; ++i) {
        bytes.insert(bytes.end(), {51, 102, 153, 102});
        shorts.insert(shorts.end(), {13107, 26214, 39321, 26214});
    }
    const int asByte = b.accessor(b.view(bytes), kUByte, 6, "VEC4", 0, true);
    const int asShort = b.accessor(b.view(shorts), kUShort, 6, "VEC4", 0, true);
    b.meshNode(json::array({quadPrimitive(b, -1, -1.0f / 3.0f, -1, 1, 0, 1, 0, 1, {{"COLOR_0", asFloat}}),
                            quadPrimitive(b, -1.0f / 3.0f, 1.0f / 3.0f, -1, 1, 0, 1, 0, 1, {{"COLOR_0", asByte}}),
                            quadPrimitive(b, 1.0f / 3.0f, 1, -1, 1, 0, 1, 0, 1, {{"COLOR_0", asShort}})}));
    Scene s = loadFramed(b.writeGltf("vertex-colors"));

    const glm::vec3 colour(0.2f, 0.4f, 0.6f);
    checkStated(std::move(s), [&](glm::vec2 p) -> std::optional<glm::vec3> {
        if (nearAny(p.x, {-1.0f / 3.0f, 1.0f / 3.0f})) return std::nullopt;
        if (p.x < -1.0f / 3.0f) return colour;
        return colour * 0.4f + kBackdrop * 0.6f;
    });
}

TEST_CASE("TextureSettingsTest, small: REPEAT, MIRRORED_REPEAT and CLAMP_TO_EDGE over u in [-1, 2]") {
    // Two texels (dark, light); u runs from -1 to 2 across each band, so the wrap decides which
    // texel every third of the band shows.
    const std::vector<std::uint8_t> texels = {40, 40, 40, 255, 220, 220, 220, 255};
    GltfBuilder b = unlitDocument();
    b.imageDataUri(encodeImage("two-greys.png", 2, 1, 4, OIIO::TypeDesc::UINT8, texels.data()));
    b.doc["samplers"] = {{{"magFilter", 9728}, {"minFilter", 9728}, {"wrapS", 10497}, {"wrapT", 33071}},
                         {{"magFilter", 9728}, {"minFilter", 9728}, {"wrapS", 33648}, {"wrapT", 33071}},
                         {{"magFilter", 9728}, {"minFilter", 9728}, {"wrapS", 33071}, {"wrapT", 33071}}};
    b.doc["textures"] = {{{"source", 0}, {"sampler", 0}}, {{"source", 0}, {"sampler", 1}}, {{"source", 0}, {"sampler", 2}}};
    for (int t = 0; t < 3; ++t) b.material(unlitMaterial({{"baseColorTexture", {{"index", t}}}}));
    b.meshNode(json::array({quadPrimitive(b, -1, 1, 1.0f / 3.0f, 1, 0, 1, -1, 2),                 // REPEAT, top
                            quadPrimitive(b, -1, 1, -1.0f / 3.0f, 1.0f / 3.0f, 0, 2, -1, 2),      // MIRRORED, middle
                            quadPrimitive(b, -1, 1, -1, -1.0f / 3.0f, 0, 3, -1, 2)}));            // CLAMP, bottom
    Scene s = loadFramed(b.writeGltf("texture-settings"));

    const glm::vec3 dark(srgbToLinear(40 / 255.0f)), light(srgbToLinear(220 / 255.0f));
    checkStated(std::move(s), [&](glm::vec2 p) -> std::optional<glm::vec3> {
        // u = -1 + 1.5 (x + 1): texel edges at every half unit of u.
        const float u = -1.0f + 1.5f * (p.x + 1.0f);
        if (nearAny(u, {-0.5f, 0.0f, 0.5f, 1.0f, 1.5f}, 0.11f) || nearAny(p.y, {-1.0f / 3.0f, 1.0f / 3.0f}))
            return std::nullopt;
        const int texel = int(std::floor(u * 2.0f));  // in texels of the unwrapped texture
        const int inPair = ((texel % 2) + 2) % 2, inFour = ((texel % 4) + 4) % 4;
        int shown = 0;
        if (p.y > 1.0f / 3.0f) shown = inPair;                           // REPEAT: period 2 texels
        else if (p.y > -1.0f / 3.0f) shown = inFour < 2 ? inFour : 3 - inFour;  // MIRRORED: 0 1 1 0
        else shown = std::clamp(texel, 0, 1);                            // CLAMP_TO_EDGE
        return shown == 0 ? dark : light;
    });
}
