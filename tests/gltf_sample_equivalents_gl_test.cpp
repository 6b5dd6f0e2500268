// Small equivalents of the Khronos glTF sample assets that define what a renderer must do with
// materials (AlphaBlendModeTest, VertexColorTest, TextureSettingsTest, TransmissionTest,
// GlassVaseFlowers), written as glTF files by the tests' own writer (gltf_test_builder.hpp),
// loaded by the loader (which must warn about nothing in them), and drawn by every exact
// technique against the CPU reference and against values stated per pixel. The first three are
// unlit (KHR_materials_unlit: the colour is the base colour), so each expected value is the
// texel or vertex colour itself, composited by its alpha mode over the unlit backdrop; the glass
// ones are lit, and state what passes through them (the image over a white backdrop less the
// image over a black one): per channel on the techniques that composite RGB transmittance, its
// mean on the others. The 16 x 16 view sees exactly [-1, 1]^2 at z = 0.
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
GltfBuilder unlitDocument(glm::vec3 backdrop = kBackdrop) {
    GltfBuilder b;
    b.doc["extensionsUsed"] = {"KHR_materials_unlit"};
    b.material({{"name", "backdrop"},
                {"pbrMetallicRoughness", {{"baseColorFactor", {backdrop.r, backdrop.g, backdrop.b, 1.0}}}},
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

void checkImagesStated(const std::vector<std::pair<std::string, Image>>& images, const Camera& camera,
                       const std::function<std::optional<glm::vec3>(glm::vec2)>& expected);

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
    checkImagesStated(images, camera, expected);
}

// Each of `images` against `expected(hit)` per pixel, within 2/255 (nullopt: not stated).
void checkImagesStated(const std::vector<std::pair<std::string, Image>>& images, const Camera& camera,
                       const std::function<std::optional<glm::vec3>(glm::vec2)>& expected) {
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

namespace {

// What passes through the scene at each pixel, per technique: the image over a white unlit
// backdrop less the image over a black one (whatever the glass reflects cancels). `build`
// writes the document's objects after the backdrop (material 0).
struct PassedThrough {
    Camera camera;
    std::vector<std::pair<std::string, Image>> images;  // the reference's, then each technique's
};

PassedThrough passedThrough(const std::vector<std::string>& extensions, const std::function<void(GltfBuilder&)>& build,
                            const std::string& name) {
    test::glContext();
    std::vector<std::pair<std::string, Image>> images[2];  // white, black
    PassedThrough out;
    for (int k = 0; k < 2; ++k) {
        GltfBuilder b = unlitDocument(glm::vec3(k == 0 ? 1.0f : 0.0f));
        for (const std::string& e : extensions) b.doc["extensionsUsed"].push_back(e);
        build(b);
        Scene s = loadFramed(b.writeGltf(name + (k == 0 ? "-white" : "-black")));
        const std::vector<Object> objects = flatten(s);
        out.camera = defaultCamera(s, objects);
        images[k].push_back({"cpu reference", raycastReference(s, objects, out.camera, kSize.x, kSize.y)});
        GpuScene gpu(std::move(s));
        for (const std::string& id : exactIds()) {
            auto t = exactTechnique(id);
            images[k].push_back({id, test::renderWith(gpu, out.camera, kSize, *t).image});
        }
    }
    for (std::size_t i = 0; i < images[0].size(); ++i) {
        Image d = images[0][i].second;
        for (std::size_t v = 0; v < d.rgba.size(); ++v) d.rgba[v] -= images[1][i].second.rgba[v];
        const std::string& id = images[0][i].first;
        // Every exact technique composites coloured filters (none keeps the scalar form).
        if (id != "cpu reference") CHECK(findTechnique(id)->info.rgbTransmittance);
        out.images.push_back({id, std::move(d)});
    }
    return out;
}

// The cosine between the view ray through the point of z = 0 at `p` and the plane's normal +z.
float facingAt(const Camera& camera, glm::vec2 p) {
    const glm::vec3 toEye = glm::normalize(camera.position - glm::vec3(p, 0.0f));
    return toEye.z;
}


}  // namespace

TEST_CASE("TransmissionTest, small: transmission 0, 0.5 and 1, a BLEND pane and ior 1 pass what they state") {
    // Five vertical bands of lit glass (roughness 0.4) over the backdrop: transmission 0 (opaque),
    // 0.5, 1, 1 at BLEND alpha 0.5, and 1 at ior 1 (no reflection, so the base colour itself).
    const glm::vec3 tint(0.9f, 0.6f, 0.3f);
    struct Band {
        float transmission, alpha, ior;
        bool blend;
    };
    const Band bands[5] = {{0.0f, 1.0f, 1.5f, false}, {0.5f, 1.0f, 1.5f, false}, {1.0f, 1.0f, 1.5f, false},
                           {1.0f, 0.5f, 1.5f, true}, {1.0f, 1.0f, 1.0f, false}};
    const PassedThrough passed = passedThrough(
        {"KHR_materials_transmission", "KHR_materials_ior"},
        [&](GltfBuilder& b) {
            json primitives = json::array();
            for (int i = 0; i < 5; ++i) {
                json m = {{"pbrMetallicRoughness",
                           {{"baseColorFactor", {tint.r, tint.g, tint.b, bands[i].alpha}}, {"metallicFactor", 0.0},
                            {"roughnessFactor", 0.4}}},
                          {"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", bands[i].transmission}}},
                                          {"KHR_materials_ior", {{"ior", bands[i].ior}}}}}};
                if (bands[i].blend) m["alphaMode"] = "BLEND";
                const float x0 = -1.0f + 0.4f * float(i);
                primitives.push_back(quadPrimitive(b, x0, x0 + 0.4f, -1, 1, 0, b.material(m)));
            }
            b.meshNode(primitives);
        },
        "transmission-test");
    checkImagesStated(passed.images, passed.camera, [&](glm::vec2 p) -> std::optional<glm::vec3> {
        if (nearAny(p.x, {-0.6f, -0.2f, 0.2f, 0.6f})) return std::nullopt;
        const Band& band = bands[std::clamp(int((p.x + 1.0f) / 0.4f), 0, 4)];
        const glm::vec3 through =
            gpu::transmissionFilter(tint, 0.0f, band.transmission, band.ior, facingAt(passed.camera, p));
        const float coverage = band.blend ? band.alpha : 1.0f;
        return glm::vec3(1.0f - coverage) + coverage * through;
    });
}

TEST_CASE("GlassVaseFlowers, small: a MASK card behind a pane of glass with a medium, over the backdrop") {
    // A pane of glass 0.5 thick (KHR_materials_volume, attenuation colour c over distance 1:
    // c^0.5 through it) in front of a MASK leaf card whose left half is cut out (alpha 0 texels):
    // through the cut the backdrop shows, filtered; behind the leaf nothing passes.
    const glm::vec3 tint(0.95f, 0.9f, 0.85f), attenuation(0.5f, 0.8f, 1.0f);
    const std::vector<std::uint8_t> texels = {60, 160, 60, 0, 60, 160, 60, 255};  // cut | leaf
    const PassedThrough passed = passedThrough(
        {"KHR_materials_transmission", "KHR_materials_volume"},
        [&](GltfBuilder& b) {
            b.imageDataUri(encodeImage("leaf.png", 2, 1, 4, OIIO::TypeDesc::UINT8, texels.data()));
            b.doc["samplers"] = {{{"magFilter", 9728}, {"minFilter", 9728}, {"wrapS", 33071}, {"wrapT", 33071}}};
            b.doc["textures"] = {{{"source", 0}, {"sampler", 0}}};
            const int leaf = b.material({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}},
                                         {"alphaMode", "MASK"}});
            const int glass = b.material(
                {{"pbrMetallicRoughness", {{"baseColorFactor", {tint.r, tint.g, tint.b, 1.0}}, {"metallicFactor", 0.0},
                                           {"roughnessFactor", 0.2}}},
                 {"extensions",
                  {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}},
                   {"KHR_materials_volume", {{"thicknessFactor", 0.5}, {"attenuationDistance", 1.0},
                                             {"attenuationColor", {attenuation.r, attenuation.g, attenuation.b}}}}}}});
            b.meshNode(json::array({quadPrimitive(b, -1, 1, -1, 1, 0, glass), quadPrimitive(b, -2, 2, -2, 2, -0.5f, leaf)}));
        },
        "glass-vase-flowers");
    checkImagesStated(passed.images, passed.camera, [&](glm::vec2 p) -> std::optional<glm::vec3> {
        // The card (4 x 4 at z = -0.5, clamped u from -0.5 to 1.5) covers the view; its cut
        // at u = 0.5 is at x = 0, which the eye on the axis sees at x = 0 too.
        if (nearAny(p.x, {0.0f})) return std::nullopt;
        if (p.x > 0.0f) return glm::vec3(0.0f);  // behind the leaf
        return gpu::transmissionFilter(tint, 0.0f, 1.0f, gpu::kDefaultIor, facingAt(passed.camera, p)) *
               glm::pow(attenuation, glm::vec3(0.5f));
    });
}
