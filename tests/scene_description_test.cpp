// Scene descriptions: the shipped scenes load, transforms and material overrides apply, and
// errors name the JSON file and the problem.
#include "test_paths.hpp"
#include "gltf_test_builder.hpp"

#include "scene/scene_description.hpp"

#include <doctest/doctest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <string>

using namespace strata;
using namespace strata::test;

namespace {

std::string descriptionError(const std::filesystem::path& file) {
    try {
        loadSceneDescription(file);
    } catch (const LoadError& e) {
        return e.what();
    }
    return "(loaded)";
}

// A quad model with one glTF material (red, opaque), written once.
std::filesystem::path quadModel() {
    static std::filesystem::path path = [] {
        GltfBuilder b;
        int pos = b.positions(kQuadPositions);
        b.material({{"name", "red"}, {"pbrMetallicRoughness", {{"baseColorFactor", {1, 0, 0, 1}}}}});
        int idx = b.accessor(b.view(std::vector<std::uint8_t>{0, 1, 2, 0, 2, 3}), kUByte, 6, "SCALAR");
        b.meshNode(json::array({{{"attributes", {{"POSITION", pos}}}, {"indices", idx}, {"material", 0}}}));
        return b.writeGltf("desc-quad");
    }();
    return path;
}

std::filesystem::path writeDescription(const std::string& name, const std::string& text) {
    auto path = tempDir() / (name + ".json");
    writeFile(path, text);
    return path;
}

bool sharedModelsPresent() {
    bool present = std::filesystem::is_directory(test::sharedScenesDir());
    if (!present) MESSAGE("skipped: " << test::sharedScenesDir().string() << " is absent");
    return present;
}

}  // namespace

TEST_CASE("scene description: the shipped scenes load") {
    if (!sharedModelsPresent()) return;
    std::filesystem::path scenes = test::sourceDir() / "scenes";

    Scene fandisk = loadSceneDescription(scenes / "fandisk-glass.json");
    CHECK(fandisk.name == "fandisk-glass");
    auto objects = flatten(fandisk);
    REQUIRE(objects.size() == 1);
    const Material& glass = fandisk.materials[std::size_t(objects[0].material)];
    CHECK(glass.alphaMode == AlphaMode::Blend);
    CHECK(glass.alpha == doctest::Approx(0.4f));
    CHECK(glass.baseColor.b > glass.baseColor.r);  // bluish
    CHECK(hasTransparency(fandisk, objects));
    CHECK(fandisk.meshes[std::size_t(objects[0].mesh)].triangleCount() == 12946);
    REQUIRE(fandisk.camera.has_value());
    CHECK(fandisk.camera->fovYDegrees == doctest::Approx(45.0f));
    // "fit": 2 centres the part at the origin with a largest extent of 2.
    Bounds b = worldBounds(fandisk, objects);
    glm::vec3 extent = b.max - b.min;
    CHECK(std::max(extent.x, std::max(extent.y, extent.z)) == doctest::Approx(2.0f).epsilon(1e-4));
    CHECK(glm::length(b.center()) < 1e-4f);

    Scene bunny = loadSceneDescription(scenes / "bunny-glass.json");
    auto bunnyObjects = flatten(bunny);
    REQUIRE(bunnyObjects.size() == 1);
    CHECK(bunny.materials[std::size_t(bunnyObjects[0].material)].alpha == doctest::Approx(0.5f));
    CHECK(hasTransparency(bunny, bunnyObjects));

    Scene opaque = loadSceneDescription(scenes / "models-opaque.json");
    auto opaqueObjects = flatten(opaque);
    CHECK(opaqueObjects.size() == 4);
    CHECK_FALSE(hasTransparency(opaque, opaqueObjects));
    // Side by side: the objects' bounds do not overlap along x.
    for (std::size_t i = 1; i < opaqueObjects.size(); ++i)
        CHECK(opaqueObjects[i - 1].worldBounds.max.x < opaqueObjects[i].worldBounds.min.x);
}

TEST_CASE("scene description: objects with the same override share one material") {
    const std::string model = quadModel().string();
    auto path = writeDescription("shared-overrides", R"({
      "objects": [
        {"model": ")" + model + R"(", "material": {"base_color": [0.1, 0.2, 0.3], "alpha": 0.5}},
        {"model": ")" + model + R"(", "translate": [2, 0, 0], "material": {"base_color": [0.1, 0.2, 0.3], "alpha": 0.5}},
        {"model": ")" + model + R"(", "translate": [4, 0, 0], "material": {"base_color": [0.1, 0.2, 0.3], "alpha": 0.25}},
        {"model": ")" + model + R"(", "translate": [6, 0, 0]}
      ]})");
    Scene s = loadSceneDescription(path);
    // default + the model's + two distinct overrides (the first two objects write theirs alike)
    CHECK(s.materials.size() == 4);
    auto objects = flatten(s);
    REQUIRE(objects.size() == 4);
    CHECK(objects[0].material == objects[1].material);
    CHECK(objects[2].material != objects[0].material);
    CHECK(s.materials[std::size_t(objects[2].material)].alpha == doctest::Approx(0.25f));
    CHECK(objects[3].material != objects[0].material);
}

TEST_CASE("scene description: transforms, overrides and merged indices") {
    std::string model = quadModel().string();
    auto path = writeDescription("two-quads", R"({
      "camera": {"position": [0, 0, 5], "target": [0, 0, 0], "fov_y_deg": 30},
      "light_direction": [0, 2, 0], "background": [0.5, 0.5, 0.5],
      "objects": [
        {"model": ")" + model + R"(", "name": "plain", "translate": [1, 2, 3], "rotate_deg": [0, 0, 90], "scale": 2},
        {"model": "desc-quad.gltf", "rotate_axis_angle": [0, 1, 0, 180], "scale": [1, 2, 3],
         "material": {"base_color": [0.1, 0.2, 0.3], "alpha": 0.25, "tau": [1, 2, 3], "albedo": [0.5, 0.5, 0.5],
                      "double_sided": false, "metallic": 0.75, "roughness": 0.25, "emissive": [0.5, 0, 0],
                      "unlit": false}}
      ]})");
    Scene s = loadSceneDescription(path);
    CHECK(s.name == "two-quads");
    CHECK(s.lightDirection == glm::vec3(0, 1, 0));
    CHECK(s.background == glm::vec3(0.5f));
    REQUIRE(s.camera.has_value());
    glm::vec3 forward = s.camera->orientation * glm::vec3(0, 0, -1);
    CHECK(forward.z == doctest::Approx(-1.0f));
    // default + red (the model, read once for both objects) + the override
    REQUIRE(s.materials.size() == 3);
    CHECK(s.materials[1].baseColor == glm::vec3(1, 0, 0));
    CHECK(s.meshes.size() == 1);
    CHECK(s.meshes[0].material == 1);
    CHECK(s.roots.size() == 2);

    auto objects = flatten(s);
    REQUIRE(objects.size() == 2);
    CHECK(objects[0].material == 1);
    glm::vec4 p = objects[0].world * glm::vec4(1, 0, 0, 1);  // scale 2, rotate 90 about z, translate
    CHECK(p.x == doctest::Approx(1.0f));
    CHECK(p.y == doctest::Approx(4.0f));
    CHECK(p.z == doctest::Approx(3.0f));
    glm::vec4 q = objects[1].world * glm::vec4(1, 1, 0, 1);  // scale (1,2,3) then 180 about y
    CHECK(q.x == doctest::Approx(-1.0f));
    CHECK(q.y == doctest::Approx(2.0f));
    CHECK(q.z == doctest::Approx(0.0f).epsilon(1e-5));

    const Material& over = s.materials[std::size_t(objects[1].material)];
    CHECK(objects[1].material == 2);
    CHECK(over.alphaMode == AlphaMode::Blend);  // alpha < 1 implies BLEND
    CHECK(over.alpha == doctest::Approx(0.25f));
    CHECK(over.tau == glm::vec3(1, 2, 3));
    CHECK(over.albedo == glm::vec3(0.5f));
    CHECK_FALSE(over.doubleSided);
    CHECK(over.metallic == doctest::Approx(0.75f));
    CHECK(over.roughness == doctest::Approx(0.25f));
    CHECK(over.emissive == glm::vec3(0.5f, 0.0f, 0.0f));
    CHECK_FALSE(over.unlit);
    CHECK(hasTransparency(s, objects));
}

TEST_CASE("scene description: a model placed N times is read once, its meshes and textures shared") {
    // Five objects place one textured model, under three spellings of its path: the scene holds
    // its mesh, material and image once, and five objects draw that mesh, each with its own
    // transform (and the one with a material override, that material).
    GltfBuilder b;
    int pos = b.positions(kQuadPositions);
    b.imageDataUri(encodeImage("shared.png", 1, 1, 4, OIIO::TypeDesc::UINT8,
                               std::vector<std::uint8_t>{200, 100, 50, 255}.data()));
    b.doc["textures"] = {{{"source", 0}}};
    int uv = b.accessor(b.view(std::vector<float>{0, 0, 1, 0, 1, 1, 0, 1}), kFloat, 4, "VEC2");
    b.material({{"name", "textured"}, {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}});
    int idx = b.accessor(b.view(std::vector<std::uint8_t>{0, 1, 2, 0, 2, 3}), kUByte, 6, "SCALAR");
    b.meshNode(json::array({{{"attributes", {{"POSITION", pos}, {"TEXCOORD_0", uv}}}, {"indices", idx}, {"material", 0}}}));
    const std::filesystem::path model = b.writeGltf("shared-model");
    const std::string name = model.filename().string();
    auto path = writeDescription("five-of-one", R"({"objects": [
        {"model": ")" + name + R"(", "translate": [0, 0, 0]},
        {"model": ")" + name + R"(", "translate": [2, 0, 0]},
        {"model": "./)" + name + R"(", "translate": [4, 0, 0], "fit": 3},
        {"model": ")" + model.string() + R"(", "translate": [6, 0, 0]},
        {"model": ")" + name + R"(", "translate": [8, 0, 0], "material": {"base_color": [0, 0, 1]}}]})");
    Scene s = loadSceneDescription(path);
    CHECK(s.meshes.size() == 1);
    CHECK(s.images.size() == 1);
    CHECK(s.materials.size() == 3);  // default, the model's, the override
    CHECK(s.roots.size() == 5);
    const std::vector<Object> objects = flatten(s);
    REQUIRE(objects.size() == 5);
    for (std::size_t i = 0; i < objects.size(); ++i) {
        CAPTURE(i);
        CHECK(objects[i].mesh == 0);
        CHECK(objects[i].material == (i == 4 ? 2 : 1));
        // The unit quad from its corner at each translation; the fitted one centred there.
        CHECK(objects[i].worldBounds.center().x == doctest::Approx(2.0f * float(i) + (i == 2 ? 0.0f : 0.5f)));
    }
    // The fitted one: the quad's largest extent (1) scaled to 3.
    CHECK(objects[2].worldBounds.max.x - objects[2].worldBounds.min.x == doctest::Approx(3.0f));
}

TEST_CASE("scene description: vectors near the float limit that can render are accepted") {
    std::string model = quadModel().string();
    // The camera's offset (6e38) and the light's length (4.2e38) overflow a float, not a double.
    auto path = writeDescription("near-limit", R"({
      "camera": {"position": [3e38, 0, 0], "target": [-3e38, 0, 0]},
      "light_direction": [3e38, 3e38, 0],
      "objects": [{"model": ")" + model + R"("}]})");
    Scene s = loadSceneDescription(path);
    CHECK(s.lightDirection.x == doctest::Approx(0.70710678f));
    CHECK(s.lightDirection.y == doctest::Approx(0.70710678f));
    REQUIRE(s.camera.has_value());
    glm::vec3 forward = s.camera->orientation * glm::vec3(0, 0, -1);
    CHECK(forward.x == doctest::Approx(-1.0f));
}

TEST_CASE("scene description: errors name the file and the problem") {
    std::string model = quadModel().string();
    auto obj = [&](const std::string& extra) {
        return R"({"objects": [{"model": ")" + model + "\"" + extra + "}]}";
    };
    struct Case { const char* name; std::string text; const char* error; };
    std::vector<Case> cases = {
        {"badjson", "{\n  \"objects\": [\n  }\n", "badjson.json: JSON parse error at line 3"},
        {"noobjects", "{}", "noobjects.json: missing field 'objects'"},
        {"emptyobjects", R"({"objects": []})", "objects: expected a non-empty array"},
        {"nomodel", R"({"objects": [{}]})", "nomodel.json: object 0: missing field 'model'"},
        {"typo", obj(R"(, "translation": [1, 2, 3])"), "typo.json: object 0: unknown key 'translation'"},
        {"badtranslate", obj(R"(, "translate": [1, "2", 3])"), "object 0: translate: expected a number"},
        {"shorttranslate", obj(R"(, "translate": [1, 2])"), "object 0: translate: expected an array of 3 numbers"},
        {"badmode", obj(R"(, "material": {"alpha_mode": "GLASS"})"), "object 0: material.alpha_mode: unknown mode 'GLASS'"},
        {"badalpha", obj(R"(, "material": {"alpha": 2})"), "object 0: material.alpha: must be in [0, 1]"},
        // 1e39 is a finite JSON number but an infinite float: tau must stay finite for the shaders.
        {"hugetau", obj(R"(, "material": {"tau": [1, 1e39, 1]})"), "object 0: material.tau: 1e+39 does not fit a float"},
        {"negativetau", obj(R"(, "material": {"tau": [-1, 0, 0]})"), "object 0: material.tau: components must be in [0, 10000]"},
        {"badscale", obj(R"(, "scale": 0)"), "object 0: scale: must not be zero"},
        {"tworotations", obj(R"(, "rotate_deg": [0, 0, 0], "rotate_axis_angle": [0, 1, 0, 90])"), "not both"},
        {"badcamera", R"({"camera": {"position": [0, 0, 0], "target": [0, 0, 0]}, "objects": []})", "camera: position and target coincide"},
        // Finite doubles that are infinite floats, each named by its key.
        {"hugetranslate", obj(R"(, "translate": [1e308, 0, 0])"), "object 0: translate: 1e+308 does not fit a float"},
        {"hugerotate", obj(R"(, "rotate_deg": [0, 1e308, 0])"), "object 0: rotate_deg: 1e+308 does not fit a float"},
        {"hugescale", obj(R"(, "scale": 1e308)"), "object 0: scale: 1e+308 does not fit a float"},
        {"hugefit", obj(R"(, "fit": 1e308)"), "object 0: fit: 1e+308 does not fit a float"},
        {"hugecamera", R"({"camera": {"position": [1e308, 0, 0], "target": [0, 0, 0]}, "objects": []})",
         "camera.position: 1e+308 does not fit a float"},
        {"hugelight", R"({"light_direction": [0, 1e308, 0], "objects": []})", "light_direction: 1e+308 does not fit a float"},
        {"hugebackground", R"({"background": [0, 0, 1e308], "objects": []})", "background: 1e+308 does not fit a float"},
        // Each part fits; together they do not. Near the float limit, a difference or a length
        // overflows a float though not a double: the camera and the light stay valid.
        {"fitoverflow", obj(R"(, "fit": 3e38, "scale": 3e38)"), "object 0: fit: the transform with the model's bounds overflows a float"},
        // JSON's own overflow: the number is not even a double. The file is named.
        {"overflow", obj(R"(, "translate": [1e400, 0, 0])"), "overflow.json: JSON number overflow parsing '1e400'"},
        {"deep", std::string(1000, '[') + std::string(1000, ']'), "deep.json: JSON nested deeper than 16 levels"},
        {"missingmodel", R"({"objects": [{"model": ")" + model + R"("}, {"model": "nowhere.glb"}]})",
         "missingmodel.json: object 1: "},
    };
    for (const Case& c : cases) {
        std::string name = c.name;
        CAPTURE(name);
        std::string error = descriptionError(writeDescription(c.name, c.text));
        CHECK(error.find(c.error) != std::string::npos);
        CHECK(error.find('\n') == std::string::npos);
    }
    std::string missing = descriptionError(tempDir() / "missingmodel.json");
    CHECK(missing.find("nowhere.glb: no such file") != std::string::npos);
    CHECK(descriptionError(tempDir() / "absent.json").find("absent.json: no such file") != std::string::npos);

    // A model that fails to load: the loader's own message follows the object number.
    GltfBuilder b;
    int pos = b.positions(kQuadPositions);
    b.meshNode(json::array({{{"attributes", {{"POSITION", pos}}},
                             {"indices", b.accessor(b.view(std::vector<std::uint8_t>{0, 1, 9}), kUByte, 3, "SCALAR")}}}));
    auto broken = b.writeGltf("broken-model");
    std::string error = descriptionError(writeDescription("broken", R"({"objects": [{"model": ")" + model +
                                                          R"("}, {"model": "broken-model.gltf"}]})"));
    CHECK(error.find("broken.json: object 1: ") != std::string::npos);
    CHECK(error.find("broken-model.gltf: mesh 0 primitive 0: index 9 out of range (4 vertices)") != std::string::npos);
}

TEST_CASE("scene description: what the glTF loader ignored in its models is passed on, once per line") {
    GltfBuilder b;
    int pos = b.positions(kQuadPositions);
    int uv = b.accessor(b.view(std::vector<float>(8, 0.5f)), kFloat, 4, "VEC2");
    int idx = b.accessor(b.view(std::vector<std::uint8_t>{0, 1, 2, 0, 2, 3}), kUByte, 6, "SCALAR");
    b.meshNode(json::array({{{"attributes", {{"POSITION", pos}, {"TEXCOORD_1", uv}}}, {"indices", idx}}}));
    auto model = b.writeGltf("desc-gap");
    // The same model placed twice: its warning is one line, naming the model file.
    auto path = writeDescription("gap", R"({"objects": [{"model": "desc-gap.gltf"}, {"model": "desc-gap.gltf",
                                            "translate": [2, 0, 0]}]})");
    std::vector<std::string> warnings;
    Scene s = loadSceneDescription(path, &warnings);
    CHECK(flatten(s).size() == 2);
    CHECK(warnings == std::vector<std::string>{
        model.string() + ": TEXCOORD_1 without TEXCOORD_0: attribute set is not contiguous, ignored (mesh 0 primitive 0)"});
    CHECK_NOTHROW(loadSceneDescription(path));  // callers that do not ask are not told
}

TEST_CASE("scene description: lod_unit makes an object, each part, or named model nodes the LOD units") {
    // A car: an axle node holding two wheels and a body beside it, all quads.
    GltfBuilder b;
    int pos = b.positions(kQuadPositions);
    int idx = b.accessor(b.view(std::vector<std::uint8_t>{0, 1, 2, 0, 2, 3}), kUByte, 6, "SCALAR");
    const json quad = json::array({{{"attributes", {{"POSITION", pos}}}, {"indices", idx}}});
    const int left = b.meshNode(quad, {{"name", "wheel"}, {"translation", {-1, 0, 0}}});
    const int right = b.meshNode(quad, {{"name", "wheel"}, {"translation", {1, 0, 0}}});
    const int body = b.meshNode(quad, {{"name", "body"}, {"translation", {0, 1, 0}}});
    b.doc["nodes"].push_back({{"name", "axle"}, {"children", {left, right}}});
    b.doc["nodes"].push_back({{"name", "car"}, {"children", {int(b.doc["nodes"].size()) - 1, body}}});
    const std::string name = b.writeGltf("lod-unit-car").filename().string();
    auto units = [&](const std::string& setting) {
        const std::string extra = setting.empty() ? "" : R"(, "lod_unit": )" + setting;
        Scene s = loadSceneDescription(writeDescription("lod-unit", R"({"objects": [
            {"model": ")" + name + R"(", "translate": [0, 0, 0])" + extra + R"(},
            {"model": ")" + name + R"(", "translate": [5, 0, 0])" + extra + R"(}]})"));
        std::vector<int> out;
        for (const Object& o : flatten(s)) out.push_back(o.unit);
        return out;
    };
    // Flatten order per placement: left wheel, right wheel, body.
    CHECK(units("") == std::vector<int>{0, 0, 0, 1, 1, 1});       // the object (default)
    CHECK(units("true") == std::vector<int>{0, 0, 0, 1, 1, 1});
    CHECK(units("false") == std::vector<int>{0, 1, 2, 3, 4, 5});  // each part
    CHECK(units("\"axle\"") == std::vector<int>{0, 0, 1, 2, 2, 3});  // the axle's wheels; the body alone
    // The wheels' transforms below their unit (the axle): each its own translation.
    {
        Scene s = loadSceneDescription(writeDescription("lod-unit-axle", R"({"objects": [
            {"model": ")" + name + R"(", "translate": [5, 0, 0], "lod_unit": "axle"}]})"));
        const std::vector<Object> objects = flatten(s);
        REQUIRE(objects.size() == 3);
        CHECK(objects[0].unitLocal[3].x == doctest::Approx(-1.0f));
        CHECK(objects[1].unitLocal[3].x == doctest::Approx(1.0f));
        CHECK(objects[0].world[3].x == doctest::Approx(4.0f));
    }
    CHECK(descriptionError(writeDescription("lod-unit-missing", R"({"objects": [
        {"model": ")" + name + R"(", "lod_unit": "nope"}]})"))
              .find("object 0: lod_unit: the model has no node named 'nope'") != std::string::npos);
    CHECK(descriptionError(writeDescription("lod-unit-type", R"({"objects": [
        {"model": ")" + name + R"(", "lod_unit": 3}]})"))
              .find("object 0: lod_unit: expected true, false or a node name") != std::string::npos);
}
