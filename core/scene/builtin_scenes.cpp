#include "scene/builtin_scenes.hpp"

#include "scene/mesh_builders.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <charconv>
#include <cmath>
#include <stdexcept>

namespace strata {
namespace {

Material transparent(const std::string& name, glm::vec3 color, float alpha) {
    Material m;
    m.name = name;
    m.baseColor = color;
    m.alpha = alpha;
    m.alphaMode = AlphaMode::Blend;
    return m;
}

Material opaque(const std::string& name, glm::vec3 color) {
    Material m;
    m.name = name;
    m.baseColor = color;
    return m;
}

Scene emptyScene(const std::string& name) {
    Scene s;
    s.name = name;
    s.materials.push_back(Material{});
    return s;
}

int placeMesh(Scene& s, int mesh, int material, const glm::mat4& local, const std::string& name) {
    Node n;
    n.name = name;
    n.local = local;
    n.meshes = {mesh};
    n.materialOverride = material;
    return s.addNode(std::move(n));
}

CameraPose lookingAt(glm::vec3 eye, glm::vec3 target, float fov) {
    CameraPose pose;
    pose.position = eye;
    glm::mat4 v = glm::lookAt(eye, target, glm::vec3(0, 1, 0));
    pose.orientation = glm::normalize(glm::conjugate(glm::quat_cast(glm::mat3(v))));
    pose.fovYDegrees = fov;
    return pose;
}

int parseCount(const std::string& spec, const std::string& text, int fallback, int lo, int hi) {
    if (text.empty()) return fallback;
    int value = 0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size() || value < lo || value > hi)
        throw std::invalid_argument("builtin:" + spec + ": argument '" + text + "' must be an integer in [" +
                                    std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return value;
}

// Full-view quads: at distance d a quad of half-size 2d covers a 50-degree view up to 4:1 aspect.
constexpr float kFirstLayer = 1.0f;
constexpr float kLayerSpacing = 0.25f;
constexpr float kSlabThickness = 0.1f;

}  // namespace

glm::vec3 paletteColor(int i) {
    float h = std::fmod(float(i) * 0.618034f, 1.0f) * 6.0f;
    float x = 1.0f - std::abs(std::fmod(h, 2.0f) - 1.0f);
    glm::vec3 c = h < 1 ? glm::vec3(1, x, 0) : h < 2 ? glm::vec3(x, 1, 0) : h < 3 ? glm::vec3(0, 1, x)
                : h < 4 ? glm::vec3(0, x, 1) : h < 5 ? glm::vec3(x, 0, 1) : glm::vec3(1, 0, x);
    return 0.15f + 0.8f * c;
}

const std::vector<BuiltinSceneInfo>& builtinScenes() {
    static const std::vector<BuiltinSceneInfo> list = {
        {"layers", "N (1..4096, default 8)", "N full-view parallel quads, depth complexity exactly N"},
        {"coplanar", "K (1..1024, default 4)", "K coincident full-view quads: one depth, K fragments"},
        {"shells", "K[:roundoff] (1..1024, default 2)",
         "K coincident transparent spheres; roundoff: the copies differ by float round-off only"},
        {"cubes", "separated (optional)", "three overlapping transparent cubes sharing face planes"},
        {"volumes", "", "intersecting transparent spheres with attenuation and albedo"},
        {"slabs", "N (1..2048, default 8)",
         "N full-view closed slabs of medium (tau, albedo), 0.1 thick: exactly 2N fragments per pixel"},
        {"default", "", "the demo room: opaque and transparent, intersecting, coplanar, a field of models"},
    };
    return list;
}

Scene makeLayersScene(int layers, float alpha) {
    Scene s = emptyScene("layers:" + std::to_string(layers));
    for (int i = 0; i < layers; ++i) {
        float d = kFirstLayer + kLayerSpacing * float(i);
        int mesh = s.addMesh(makeQuad(4.0f * d, 4.0f * d));
        int material = s.addMaterial(transparent("layer" + std::to_string(i), paletteColor(i), alpha));
        placeMesh(s, mesh, material, glm::translate(glm::mat4(1.0f), {0, 0, -d}), "layer" + std::to_string(i));
    }
    s.camera = CameraPose{};
    s.lightDirection = {0, 0, 1};
    return s;
}

Scene makeSlabsScene(int slabs) {
    Scene s = emptyScene("slabs:" + std::to_string(slabs));
    for (int i = 0; i < slabs; ++i) {
        // Front face at d, back face 0.1 behind; the half-size covers the view at the back face.
        const float d = kFirstLayer + kLayerSpacing * float(i), back = d + kSlabThickness, half = 2.0f * back;
        int mesh = s.addMesh(makeBox({-half, -half, -back}, {half, half, -d}));
        Material m = transparent("slab" + std::to_string(i), paletteColor(i), 0.5f);
        m.volume = true;
        m.tau = 1.0f + 3.0f * paletteColor(i + 1);
        m.albedo = paletteColor(i);
        placeMesh(s, mesh, s.addMaterial(m), glm::mat4(1.0f), "slab" + std::to_string(i));
    }
    s.camera = CameraPose{};
    s.lightDirection = {0, 0, 1};
    return s;
}

Scene makeCoplanarScene(int copies, float alpha) {
    Scene s = emptyScene("coplanar:" + std::to_string(copies));
    int mesh = s.addMesh(makeQuad(8.0f, 8.0f));
    for (int i = 0; i < copies; ++i) {
        int material = s.addMaterial(transparent("copy" + std::to_string(i), paletteColor(i), alpha));
        placeMesh(s, mesh, material, glm::translate(glm::mat4(1.0f), {0, 0, -2.0f}), "copy" + std::to_string(i));
    }
    s.camera = CameraPose{};
    s.lightDirection = {0, 0, 1};
    return s;
}

Scene makeShellsScene(int copies, bool roundoff) {
    Scene s = emptyScene("shells:" + std::to_string(copies) + (roundoff ? ":roundoff" : ""));
    int mesh = s.addMesh(makeSphere(1.0f, 40, 20));
    const glm::vec3 centre(0.3f, -0.2f, -4.0f);
    for (int i = 0; i < copies; ++i) {
        int material = s.addMaterial(transparent("shell" + std::to_string(i), paletteColor(i), 0.45f));
        glm::mat4 world = glm::translate(glm::mat4(1.0f), centre);
        // Copy i scaled by 1 + i * 1.2e-7 (one float ulp of 1 per copy) and placed through an
        // offset there and back: the same surface up to round-off, as when one model is placed
        // twice by different transforms.
        if (roundoff && i > 0) {
            const glm::vec3 offset(0.37f * float(i), -0.11f, 0.23f);
            world = glm::translate(glm::translate(world, offset), -offset) *
                    glm::scale(glm::mat4(1.0f), glm::vec3(1.0f + 1.2e-7f * float(i)));
        }
        placeMesh(s, mesh, material, world, "shell" + std::to_string(i));
    }
    s.camera = lookingAt({0.0f, 0.0f, 0.0f}, centre + glm::vec3(0.2f, 0.1f, 0.0f), 40.0f);
    s.lightDirection = glm::normalize(glm::vec3(0.4f, 0.7f, 0.6f));
    return s;
}

Scene makeCubesScene(bool separated) {
    Scene s = emptyScene(separated ? "cubes:separated" : "cubes");
    // Unit cubes overlapping by half: A and B share their top, bottom, front and back planes where
    // they overlap, C shares the front and back planes with both (the depth-fighting paper's case).
    float e = separated ? 0.02f : 0.0f;
    int a = s.addMesh(makeBox({0, 0, 0}, {1, 1, 1}));
    int b = s.addMesh(makeBox({0.5f, e, e}, {1.5f, 1 - e, 1 - e}));
    int c = s.addMesh(makeBox({0.25f, 0.5f, 2 * e}, {1.25f, 1.5f, 1 - 2 * e}));
    placeMesh(s, a, s.addMaterial(transparent("red", {0.9f, 0.15f, 0.1f}, 0.4f)), glm::mat4(1.0f), "A");
    placeMesh(s, b, s.addMaterial(transparent("green", {0.1f, 0.85f, 0.2f}, 0.4f)), glm::mat4(1.0f), "B");
    placeMesh(s, c, s.addMaterial(transparent("blue", {0.15f, 0.3f, 0.95f}, 0.4f)), glm::mat4(1.0f), "C");
    int floor = s.addMesh(makeBox({-2, -0.1f, -2}, {3.5f, 0, 3}));
    placeMesh(s, floor, s.addMaterial(opaque("floor", {0.6f, 0.6f, 0.55f})), glm::mat4(1.0f), "floor");
    s.camera = lookingAt({2.6f, 2.2f, 3.4f}, {0.75f, 0.6f, 0.5f}, 45.0f);
    return s;
}

Scene makeVolumesScene() {
    Scene s = emptyScene("volumes");
    int sphere = s.addMesh(makeSphere(1.0f, 48, 24));
    struct V { glm::vec3 at; glm::vec3 color; glm::vec3 tau; };
    const V volumes[3] = {{{-0.55f, 1.0f, 0.0f}, {0.9f, 0.3f, 0.2f}, {0.4f, 1.6f, 2.0f}},
                          {{0.55f, 1.0f, 0.0f}, {0.2f, 0.5f, 0.95f}, {2.0f, 1.0f, 0.3f}},
                          {{0.0f, 1.8f, 0.4f}, {0.3f, 0.9f, 0.3f}, {1.5f, 0.3f, 1.5f}}};
    int i = 0;
    for (const V& v : volumes) {
        Material m = transparent("volume" + std::to_string(i), v.color, 0.35f);
        m.tau = v.tau;
        m.albedo = v.color;
        m.volume = true;
        placeMesh(s, sphere, s.addMaterial(m), glm::translate(glm::mat4(1.0f), v.at), "volume" + std::to_string(i));
        ++i;
    }
    int floor = s.addMesh(makeBox({-3, -0.1f, -3}, {3, 0, 3}));
    placeMesh(s, floor, s.addMaterial(opaque("floor", {0.55f, 0.55f, 0.5f})), glm::mat4(1.0f), "floor");
    s.camera = lookingAt({0.0f, 2.4f, 4.6f}, {0.0f, 1.2f, 0.0f}, 45.0f);
    return s;
}

Scene makeDefaultScene() {
    Scene s = emptyScene("default");
    // The room: floor, back and left walls, two pedestals (opaque).
    int wallMat = s.addMaterial(opaque("wall", {0.75f, 0.72f, 0.66f}));
    int floorMat = s.addMaterial(opaque("floor", {0.45f, 0.42f, 0.4f}));
    int pedestalMat = s.addMaterial(opaque("pedestal", {0.3f, 0.32f, 0.38f}));
    placeMesh(s, s.addMesh(makeBox({-5, -0.2f, -5}, {5, 0, 5})), floorMat, glm::mat4(1.0f), "floor");
    placeMesh(s, s.addMesh(makeBox({-5, 0, -5.2f}, {5, 4, -5})), wallMat, glm::mat4(1.0f), "back wall");
    placeMesh(s, s.addMesh(makeBox({-5.2f, 0, -5}, {-5, 4, 5})), wallMat, glm::mat4(1.0f), "left wall");
    int pedestal = s.addMesh(makeBox({-0.5f, 0, -0.5f}, {0.5f, 0.8f, 0.5f}));
    placeMesh(s, pedestal, pedestalMat, glm::translate(glm::mat4(1.0f), {-2.0f, 0, -1.5f}), "pedestal L");
    placeMesh(s, pedestal, pedestalMat, glm::translate(glm::mat4(1.0f), {2.0f, 0, -1.5f}), "pedestal R");

    // A glass cube on the left pedestal and two intersecting volumes on the right one.
    int cube = s.addMesh(makeBox({-0.45f, 0, -0.45f}, {0.45f, 0.9f, 0.45f}));
    placeMesh(s, cube, s.addMaterial(transparent("glass", {0.6f, 0.85f, 0.95f}, 0.3f)),
              glm::translate(glm::mat4(1.0f), {-2.0f, 0.8f, -1.5f}), "glass cube");
    int sphere = s.addMesh(makeSphere(0.5f, 40, 20));
    Material red = transparent("red volume", {0.95f, 0.3f, 0.2f}, 0.4f);
    red.tau = {0.5f, 2.5f, 3.0f};
    red.albedo = red.baseColor;
    red.volume = true;
    Material blue = transparent("blue volume", {0.2f, 0.45f, 0.95f}, 0.4f);
    blue.tau = {3.0f, 1.5f, 0.4f};
    blue.albedo = blue.baseColor;
    blue.volume = true;
    placeMesh(s, sphere, s.addMaterial(red), glm::translate(glm::mat4(1.0f), {1.75f, 1.3f, -1.5f}), "red volume");
    placeMesh(s, sphere, s.addMaterial(blue), glm::translate(glm::mat4(1.0f), {2.25f, 1.3f, -1.4f}), "blue volume");

    // Coplanar panels: two overlapping quads in one plane, in front of the back wall.
    int panel = s.addMesh(makeQuad(1.6f, 1.2f));
    placeMesh(s, panel, s.addMaterial(transparent("panel yellow", {0.95f, 0.85f, 0.2f}, 0.5f)),
              glm::translate(glm::mat4(1.0f), {-0.4f, 2.2f, -3.5f}), "panel A");
    placeMesh(s, panel, s.addMaterial(transparent("panel magenta", {0.85f, 0.2f, 0.8f}, 0.5f)),
              glm::translate(glm::mat4(1.0f), {0.4f, 2.0f, -3.5f}), "panel B");

    // A field of repeated models in front: alternating opaque and transparent spheres and boxes.
    int small = s.addMesh(makeSphere(0.22f, 20, 10));
    int smallBox = s.addMesh(makeBox({-0.18f, -0.18f, -0.18f}, {0.18f, 0.18f, 0.18f}));
    for (int z = 0; z < 4; ++z)
        for (int x = 0; x < 8; ++x) {
            int i = z * 8 + x;
            bool isTransparent = (x + z) % 2 == 0;
            Material m = isTransparent ? transparent("field", paletteColor(i), 0.45f) : opaque("field", paletteColor(i));
            glm::vec3 at(-3.5f + float(x), 0.25f, 0.5f + 1.0f * float(z));
            placeMesh(s, (i % 3 == 0) ? smallBox : small, s.addMaterial(m), glm::translate(glm::mat4(1.0f), at),
                      "field " + std::to_string(i));
        }
    s.camera = lookingAt({1.5f, 3.2f, 7.5f}, {0.0f, 1.0f, -1.0f}, 50.0f);
    return s;
}

Scene makeBuiltinScene(const std::string& spec) {
    auto colon = spec.find(':');
    std::string name = spec.substr(0, colon);
    std::string arg = colon == std::string::npos ? "" : spec.substr(colon + 1);
    if (name == "layers") return makeLayersScene(parseCount(spec, arg, 8, 1, 4096));
    if (name == "coplanar") return makeCoplanarScene(parseCount(spec, arg, 4, 1, 1024));
    if (name == "shells") {
        auto second = arg.find(':');
        std::string option = second == std::string::npos ? "" : arg.substr(second + 1);
        if (!option.empty() && option != "roundoff")
            throw std::invalid_argument("builtin:" + spec + ": the only option of shells is 'roundoff'");
        return makeShellsScene(parseCount(spec, arg.substr(0, second), 2, 1, 1024), option == "roundoff");
    }
    if (name == "cubes") {
        if (!arg.empty() && arg != "separated")
            throw std::invalid_argument("builtin:" + spec + ": the only argument of cubes is 'separated'");
        return makeCubesScene(arg == "separated");
    }
    if (name == "volumes" && arg.empty()) return makeVolumesScene();
    if (name == "slabs") return makeSlabsScene(parseCount(spec, arg, 8, 1, 2048));
    if (name == "default" && arg.empty()) return makeDefaultScene();
    std::string known;
    for (const auto& b : builtinScenes()) known += (known.empty() ? "" : ", ") + b.name;
    throw std::invalid_argument("builtin:" + spec + ": unknown builtin scene (known: " + known + ")");
}

}  // namespace strata
