#include "scene/builtin_scenes.hpp"

#include "scene/mesh_builders.hpp"
#include "scene/wireframe.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string_view>

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

// "N[:option]" of a scene that takes a count and one of `options`: the count (`fallback` when
// empty) and the option ("" when none). Names the allowed options when another is given.
struct CountAndOption {
    int count = 0;
    std::string option;
};
CountAndOption parseCountAndOption(const std::string& spec, const std::string& name, const std::string& arg,
                                   int fallback, int lo, int hi, const std::vector<std::string>& options) {
    const auto second = arg.find(':');
    CountAndOption out;
    out.option = second == std::string::npos ? "" : arg.substr(second + 1);
    if (second != std::string::npos && std::find(options.begin(), options.end(), out.option) == options.end()) {
        std::string list;
        for (std::size_t i = 0; i < options.size(); ++i)
            list += (i == 0 ? "" : i + 1 == options.size() ? " and " : ", ") + ("'" + options[i] + "'");
        throw std::invalid_argument("builtin:" + spec + (options.size() == 1 ? ": the only option of " + name + " is "
                                                                              : ": the options of " + name + " are ") +
                                    list);
    }
    out.count = parseCount(spec, arg.substr(0, second), fallback, lo, hi);
    return out;
}

// Full-view quads: at distance d a quad of half-size 2d covers a 50-degree view up to 4:1 aspect.
constexpr float kFirstLayer = 1.0f;
constexpr float kLayerSpacing = 0.25f;
constexpr float kSlabThickness = 0.1f;

// A quad (makeQuad) with TEXCOORD_0 spanning the whole texture, v = 0 at the top edge.
Mesh texturedQuad(float width, float height) {
    Mesh m = makeQuad(width, height);
    for (const auto& p : m.positions) m.texCoords[0].push_back({p.x / width + 0.5f, 0.5f - p.y / height});
    return m;
}

// Procedural textures for the demo room, small and drawn with NEAREST filtering: the GPU then
// reads level 0 as the CPU reference does, so the room stays an exact test case whatever its
// size on screen (texture_sampling.hpp: the reference has no mip levels).
Sampler blockySampler() {
    Sampler s;
    s.magFilter = s.minFilter = TextureFilter::Nearest;
    s.wrapS = s.wrapT = TextureWrap::ClampToEdge;
    return s;
}

TextureImage proceduralTexture(const std::string& name, int size, glm::u8vec4 (*texel)(float u, float v)) {
    TextureImage image;
    image.name = name;
    image.width = image.height = size;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const glm::u8vec4 c = texel((float(x) + 0.5f) / float(size), (float(y) + 0.5f) / float(size));
            image.rgba.insert(image.rgba.end(), {c.r, c.g, c.b, c.a});
        }
    return image;
}

// Foliage for a MASK card: five leaves (ellipses) on a stem; alpha 255 on a leaf, 0 around it.
glm::u8vec4 leafTexel(float u, float v) {
    const glm::vec2 p(u, v);
    const glm::vec2 centres[5] = {{0.5f, 0.22f}, {0.3f, 0.42f}, {0.7f, 0.48f}, {0.34f, 0.7f}, {0.66f, 0.76f}};
    for (int i = 0; i < 5; ++i) {
        const glm::vec2 d = (p - centres[i]) / glm::vec2(0.16f, 0.11f);
        if (glm::dot(d, d) <= 1.0f) return {std::uint8_t(40 + 25 * i), std::uint8_t(150 + 15 * (i % 3)), 50, 255};
    }
    if (std::abs(u - 0.5f) < 0.03f && v > 0.2f) return {90, 70, 40, 255};  // the stem
    return {30, 90, 30, 0};
}

// Stained glass for a BLEND pane: coloured cells (alpha 0.55) between opaque dark leading.
glm::u8vec4 stainedGlassTexel(float u, float v) {
    const int cx = int(u * 4.0f), cy = int(v * 4.0f);
    const float fu = u * 4.0f - float(cx), fv = v * 4.0f - float(cy);
    if (fu < 0.12f || fv < 0.12f || u > 0.97f || v > 0.97f) return {25, 25, 30, 255};
    const glm::u8vec4 colours[4] = {{220, 40, 40, 140}, {40, 90, 220, 140}, {240, 200, 40, 140}, {40, 180, 90, 140}};
    return colours[(cx + 2 * cy) % 4];
}

// An emblem decal: a white ring with a red centre, transparent outside it.
glm::u8vec4 emblemTexel(float u, float v) {
    const float r = glm::length(glm::vec2(u, v) - glm::vec2(0.5f));
    if (r < 0.22f) return {230, 30, 30, 230};
    if (r < 0.42f) return {250, 250, 245, 200};
    return {0, 0, 0, 0};
}

int texturedMaterial(Scene& s, Material m, TextureImage image) {
    s.images.push_back(std::move(image));
    m.baseColorTexture.image = int(s.images.size()) - 1;
    m.baseColorTexture.sampler = blockySampler();
    return s.addMaterial(std::move(m));
}

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
        {"layers", "N[:textured|lit|glass] (1..4096, default 8)",
         "N full-view parallel unlit quads, depth complexity exactly N; textured: through a white texture; lit: "
         "shaded, alpha 0.5; glass: shaded coloured glass (transmission 1), the same scene with coloured filters"},
        {"coplanar", "K (1..1024, default 4)", "K coincident full-view quads: one depth, K fragments"},
        {"shells", "K[:roundoff] (1..1024, default 2)",
         "K coincident transparent spheres; roundoff: the copies differ by float round-off only"},
        {"cubes", "separated (optional)", "three overlapping transparent cubes sharing face planes"},
        {"volumes", "", "intersecting transparent spheres with attenuation and albedo"},
        {"slabs", "N (1..2048, default 8)",
         "N full-view closed slabs of medium (tau, albedo), 0.1 thick: exactly 2N fragments per pixel"},
        {"field", "N[:transparent] (1..1000, default 100)",
         "N instances of one dense mesh (46080 triangles) on a grid over an opaque ground: the impostor LOD bench"},
        {"orchard", "N[:glass] (1..100000, default 1000)",
         "N instances of a four-part tree model (a trunk and three crown blobs, two materials) on a grid over an "
         "opaque ground, each instance a LOD unit: the scene graph at scale; glass: the crowns transparent"},
        {"default", "", "the demo room: interpenetrating glass, a decal on a transparent panel in front of coloured "
                        "glass behind glass (transmission), a stained-glass pane, a foliage card, a wireframe over "
                        "its surface, volumes, dense opaque detail behind"},
    };
    return list;
}

Scene makeLayersScene(int layers, float alpha, bool textured) {
    Scene s = emptyScene("layers:" + std::to_string(layers) + (textured ? ":textured" : ""));
    if (textured) {
        TextureImage white;
        white.name = "white";
        white.width = white.height = 64;
        white.rgba.assign(64 * 64 * 4, 255);
        s.images.push_back(std::move(white));
    }
    for (int i = 0; i < layers; ++i) {
        float d = kFirstLayer + kLayerSpacing * float(i);
        int mesh = s.addMesh(textured ? texturedQuad(4.0f * d, 4.0f * d) : makeQuad(4.0f * d, 4.0f * d));
        Material m = transparent("layer" + std::to_string(i), paletteColor(i), alpha);
        if (textured) m.baseColorTexture.image = 0;  // the default sampler: trilinear, repeat
        // Unlit: a layer's colour is its base colour, as the closed forms take it and as the
        // peers (tools/peers) draw their layers, so the bench compares compositing alone.
        m.unlit = true;
        int material = s.addMaterial(m);
        placeMesh(s, mesh, material, glm::translate(glm::mat4(1.0f), {0, 0, -d}), "layer" + std::to_string(i));
    }
    s.camera = CameraPose{};
    s.lightDirection = {0, 0, 1};
    return s;
}

Scene makeLitLayersScene(int layers, bool glass) {
    Scene s = emptyScene("layers:" + std::to_string(layers) + (glass ? ":glass" : ":lit"));
    for (int i = 0; i < layers; ++i) {
        float d = kFirstLayer + kLayerSpacing * float(i);
        Material m = glass ? opaque("glass" + std::to_string(i), paletteColor(i))
                           : transparent("layer" + std::to_string(i), paletteColor(i), 0.5f);
        m.roughness = 0.5f;
        if (glass) m.transmission = 1.0f;
        placeMesh(s, s.addMesh(makeQuad(4.0f * d, 4.0f * d)), s.addMaterial(m), glm::translate(glm::mat4(1.0f), {0, 0, -d}),
                  m.name);
    }
    s.camera = CameraPose{};
    s.lightDirection = glm::normalize(glm::vec3(0.3f, 0.4f, 1.0f));
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

// Boxes appended to one mesh: dense detail as one object (one draw), not hundreds.
static void appendBox(Mesh& into, const glm::vec3& min, const glm::vec3& max) {
    const Mesh box = makeBox(min, max);
    const auto base = std::uint32_t(into.positions.size());
    into.positions.insert(into.positions.end(), box.positions.begin(), box.positions.end());
    into.normals.insert(into.normals.end(), box.normals.begin(), box.normals.end());
    for (std::uint32_t i : box.indices) into.indices.push_back(base + i);
}

Scene makeDefaultScene() {
    // Built so that the views have something to show from the first frame (issue 8): glass that
    // interpenetrates, a decal coplanar with a transparent panel, a translucent wireframe over
    // its own surface (Fig. 12), and dense opaque detail behind all of it. Object order is the
    // tie rule's order for coincident surfaces: the decal and the wireframe come before the
    // surfaces they lie on, so they composite in front.
    Scene s = emptyScene("default");
    const glm::mat4 identity(1.0f);

    // In front of the surfaces they lie on (lower object ids).
    // A decal on a tilted transparent panel: both quads in the panel's plane, the decal offset
    // within it, so their depths agree only up to round-off.
    const glm::mat4 panelPlane = glm::rotate(glm::translate(identity, {-0.2f, 2.3f, -2.6f}), glm::radians(-18.0f),
                                             glm::vec3(0, 1, 0));
    placeMesh(s, s.addMesh(makeQuad(0.9f, 0.5f)), s.addMaterial(transparent("decal", {0.95f, 0.8f, 0.15f}, 0.75f)),
              glm::translate(panelPlane, {0.35f, -0.15f, 0.0f}), "decal");
    // A textured emblem decal on a stained-glass pane (both BLEND textures, in one plane).
    const glm::mat4 glassPlane = glm::rotate(glm::translate(identity, {3.3f, 2.1f, 0.2f}), glm::radians(-35.0f),
                                             glm::vec3(0, 1, 0));
    placeMesh(s, s.addMesh(texturedQuad(0.6f, 0.6f)),
              texturedMaterial(s, transparent("emblem", glm::vec3(1.0f), 1.0f), proceduralTexture("emblem", 32, emblemTexel)),
              glm::translate(glassPlane, {0.1f, 0.15f, 0.0f}), "emblem decal");
    // A translucent globe with its wireframe: edge strips in the globe's own triangle planes.
    const Mesh globe = makeSphere(0.65f, 14, 7);
    const glm::mat4 globeAt = glm::translate(identity, {0.2f, 0.75f, 0.4f});
    placeMesh(s, s.addMesh(makeWireframeMesh(globe, globeAt, 0.012f)),
              s.addMaterial(transparent("wireframe", {0.9f, 0.95f, 1.0f}, 0.6f)), globeAt, "globe wireframe");

    // The surfaces.
    placeMesh(s, s.addMesh(makeQuad(2.2f, 1.5f)), s.addMaterial(transparent("panel", {0.55f, 0.75f, 0.95f}, 0.3f)),
              panelPlane, "panel");
    placeMesh(s, s.addMesh(globe), s.addMaterial(transparent("globe", {0.3f, 0.8f, 0.45f}, 0.25f)), globeAt, "globe");
    placeMesh(s, s.addMesh(texturedQuad(1.4f, 1.6f)),
              texturedMaterial(s, transparent("stained glass", glm::vec3(1.0f), 1.0f),
                               proceduralTexture("stained glass", 32, stainedGlassTexel)),
              glassPlane, "stained glass");
    // A foliage card: MASK, cut out by its texture's alpha in every pass.
    Material foliage = opaque("foliage", glm::vec3(1.0f));
    foliage.alphaMode = AlphaMode::Mask;
    foliage.alphaCutoff = 0.5f;
    placeMesh(s, s.addMesh(texturedQuad(1.3f, 1.7f)), texturedMaterial(s, foliage, proceduralTexture("leaves", 32, leafTexel)),
              glm::rotate(glm::translate(identity, {-3.4f, 0.85f, 0.6f}), glm::radians(30.0f), glm::vec3(0, 1, 0)),
              "foliage card");

    // Interpenetrating glass: a box turned on the left pedestal with a sphere through its corner.
    // Glossy: the light's highlight shows on every glass surface (roughness 0.3).
    Material glassMaterial = transparent("glass", {0.6f, 0.85f, 0.95f}, 0.3f);
    glassMaterial.roughness = 0.3f;
    int glass = s.addMaterial(glassMaterial);
    placeMesh(s, s.addMesh(makeBox({-0.45f, 0, -0.45f}, {0.45f, 0.9f, 0.45f})), glass,
              glm::rotate(glm::translate(identity, {-2.0f, 0.8f, -1.5f}), glm::radians(30.0f), glm::vec3(0, 1, 0)),
              "glass box");
    Material glassSphere = transparent("glass sphere", {0.85f, 0.6f, 0.9f}, 0.35f);
    glassSphere.roughness = 0.3f;
    placeMesh(s, s.addMesh(makeSphere(0.45f, 32, 16)), s.addMaterial(glassSphere),
              glm::translate(identity, {-1.6f, 1.65f, -1.2f}), "glass sphere");
    // Glass behind glass behind a BLEND decal: two thin panes of coloured transmissive glass
    // (KHR_materials_transmission, OPAQUE) behind the decal's panel, overlapping. Where they
    // overlap, the techniques that composite RGB transmittance pass the product of the tints
    // (amber x cyan: green); the others pass a grey of the same brightness (`strata modes`).
    Material amber = opaque("amber glass", {1.0f, 0.55f, 0.1f});
    amber.transmission = 1.0f;
    amber.roughness = 0.15f;
    Material cyan = opaque("cyan glass", {0.1f, 0.8f, 1.0f});
    cyan.transmission = 1.0f;
    cyan.roughness = 0.15f;
    const int pane = s.addMesh(makeQuad(1.6f, 1.3f));
    placeMesh(s, pane, s.addMaterial(amber),
              glm::rotate(glm::translate(identity, {-0.55f, 1.75f, -3.3f}), glm::radians(12.0f), glm::vec3(0, 1, 0)),
              "amber glass");
    placeMesh(s, pane, s.addMaterial(cyan),
              glm::rotate(glm::translate(identity, {0.25f, 1.45f, -3.9f}), glm::radians(-10.0f), glm::vec3(0, 1, 0)),
              "cyan glass");
    // Two intersecting volumes on the right pedestal (media for ll-volume / abuffer-volume).
    int sphere = s.addMesh(makeSphere(0.5f, 40, 20));
    Material red = transparent("red volume", {0.95f, 0.3f, 0.2f}, 0.4f);
    red.tau = {0.5f, 2.5f, 3.0f};
    red.albedo = red.baseColor;
    red.volume = true;
    Material blue = transparent("blue volume", {0.2f, 0.45f, 0.95f}, 0.4f);
    blue.tau = {3.0f, 1.5f, 0.4f};
    blue.albedo = blue.baseColor;
    blue.volume = true;
    placeMesh(s, sphere, s.addMaterial(red), glm::translate(identity, {1.75f, 1.3f, -1.5f}), "red volume");
    placeMesh(s, sphere, s.addMaterial(blue), glm::translate(identity, {2.25f, 1.3f, -1.4f}), "blue volume");

    // The opaque room: floor, back and left walls, two pedestals.
    int wallMat = s.addMaterial(opaque("wall", {0.75f, 0.72f, 0.66f}));
    // Brushed steel: a metal (no diffuse term, a tinted highlight) beside the dielectrics.
    Material steel = opaque("pedestal", {0.62f, 0.63f, 0.66f});
    steel.metallic = 1.0f;
    steel.roughness = 0.5f;
    int pedestalMat = s.addMaterial(steel);
    placeMesh(s, s.addMesh(makeBox({-5, -0.2f, -5}, {5, 0, 5})), s.addMaterial(opaque("floor", {0.45f, 0.42f, 0.4f})),
              identity, "floor");
    placeMesh(s, s.addMesh(makeBox({-5, 0, -5.2f}, {5, 4, -5})), wallMat, identity, "back wall");
    placeMesh(s, s.addMesh(makeBox({-5.2f, 0, -5}, {-5, 4, 5})), wallMat, identity, "left wall");
    int pedestal = s.addMesh(makeBox({-0.5f, 0, -0.5f}, {0.5f, 0.8f, 0.5f}));
    placeMesh(s, pedestal, pedestalMat, glm::translate(identity, {-2.0f, 0, -1.5f}), "pedestal L");
    placeMesh(s, pedestal, pedestalMat, glm::translate(identity, {2.0f, 0, -1.5f}), "pedestal R");

    // Dense opaque detail behind everything: a relief of blocks of varied depth and height on the
    // back wall, three colours, each colour one object.
    Mesh relief[3];
    for (int row = 0; row < 9; ++row)
        for (int col = 0; col < 20; ++col) {
            const int i = row * 20 + col;
            const float depth = 0.08f + 0.07f * float((i * 7) % 5), height = 0.18f + 0.04f * float((i * 3) % 4);
            const glm::vec3 at(-4.6f + 0.46f * float(col), 0.2f + 0.4f * float(row), -5.0f);
            appendBox(relief[i % 3], at, at + glm::vec3(0.38f, height, depth));
        }
    const glm::vec3 reliefColours[3] = {{0.8f, 0.45f, 0.3f}, {0.35f, 0.5f, 0.7f}, {0.85f, 0.8f, 0.6f}};
    for (int k = 0; k < 3; ++k)
        placeMesh(s, s.addMesh(std::move(relief[k])), s.addMaterial(opaque("relief", reliefColours[k])), identity,
                  "relief " + std::to_string(k));

    // A row of small models in front, alternating opaque and transparent.
    int small = s.addMesh(makeSphere(0.22f, 20, 10));
    int smallBox = s.addMesh(makeBox({-0.18f, -0.18f, -0.18f}, {0.18f, 0.18f, 0.18f}));
    for (int x = 0; x < 8; ++x) {
        const bool isTransparent = x % 2 == 0;
        Material m = isTransparent ? transparent("field", paletteColor(x), 0.45f) : opaque("field", paletteColor(x));
        placeMesh(s, (x % 3 == 0) ? smallBox : small, s.addMaterial(m),
                  glm::translate(identity, {-3.5f + float(x), 0.25f, 2.0f}), "field " + std::to_string(x));
    }
    s.camera = lookingAt({1.5f, 3.2f, 7.5f}, {0.0f, 1.0f, -1.0f}, 50.0f);
    return s;
}

namespace {

// A grid of `count` places about as wide as deep, `spacing` apart, rows going away from the
// camera (-Z), centred in x, at height y; then the ground under it and the camera looking over it
// from in front and above (the near rows large, the far rows small). The field's and the orchard's.
struct InstanceGrid {
    float spacing;
    int columns, rows;  // declared in this order: rows needs columns
    InstanceGrid(int count, float step)
        : spacing(step), columns(int(std::ceil(std::sqrt(double(count))))), rows((count + columns - 1) / columns) {}
    glm::vec3 at(int i, float y) const {
        return {(float(i % columns) - 0.5f * float(columns - 1)) * spacing, y, -float(i / columns) * spacing};
    }
    void addGroundAndCamera(Scene& s) const {
        const float halfWidth = 0.5f * float(columns) * spacing + 2.0f, depth = float(rows) * spacing;
        placeMesh(s, s.addMesh(makeBox({-halfWidth, -0.1f, -depth - 2.0f}, {halfWidth, 0.0f, 0.5f * spacing + 2.0f})),
                  s.addMaterial(opaque("ground", {0.42f, 0.45f, 0.38f})), glm::mat4(1.0f), "ground");
        const float extent = std::max(2.0f * halfWidth, depth);
        s.camera = lookingAt({0.0f, 2.0f + 0.3f * extent, 3.0f + 0.45f * extent}, {0.0f, 0.0f, -0.4f * depth}, 50.0f);
    }
};

}  // namespace

Scene makeFieldScene(int count, bool transparentInstances) {
    if (count < 1 || count > kFieldMaxInstances)
        throw std::invalid_argument("field: " + std::to_string(count) + " instances is outside 1.." +
                                    std::to_string(kFieldMaxInstances));
    Scene s = emptyScene("field:" + std::to_string(count) + (transparentInstances ? ":transparent" : ""));
    // One mesh for every instance: the case impostors are for (one bake, many draws).
    const int blob = s.addMesh(makeBumpyBlob(kFieldMeshSegments));
    constexpr int kColours = 6;
    int materials[kColours];
    for (int k = 0; k < kColours; ++k)
        materials[k] = s.addMaterial(transparentInstances ? transparent("field" + std::to_string(k), paletteColor(k), 0.5f)
                                                          : opaque("field" + std::to_string(k), paletteColor(k)));
    // 3 units apart: the blob is about 2 x 1.7 x 1.5.
    const InstanceGrid grid(count, 3.0f);
    for (int i = 0; i < count; ++i) {
        // Varied orientation: golden-angle turns about the vertical, a tilt of -20..+20 degrees.
        glm::mat4 world = glm::translate(glm::mat4(1.0f), grid.at(i, 1.0f));
        world = glm::rotate(world, glm::radians(137.508f * float(i)), glm::vec3(0, 1, 0));
        world = glm::rotate(world, glm::radians(float((i * 53) % 41) - 20.0f), glm::vec3(1, 0, 0));
        placeMesh(s, blob, materials[i % kColours], world, "instance " + std::to_string(i));
    }
    grid.addGroundAndCamera(s);
    return s;
}

Scene makeOrchardScene(int count, bool glassCrowns) {
    if (count < 1 || count > kOrchardMaxInstances)
        throw std::invalid_argument("orchard: " + std::to_string(count) + " instances is outside 1.." +
                                    std::to_string(kOrchardMaxInstances));
    Scene s = emptyScene("orchard:" + std::to_string(count) + (glassCrowns ? ":glass" : ""));
    // The model, once: a trunk and three crown blobs below one node the instances place.
    const int trunkMesh = s.addMesh(makeBox({-0.12f, 0.0f, -0.12f}, {0.12f, 1.2f, 0.12f}));
    const int crownMesh = s.addMesh(makeBumpyBlob(kOrchardBlobSegments, 0.55f));
    const int bark = s.addMaterial(opaque("bark", {0.35f, 0.22f, 0.12f}));
    constexpr int kCrownColours = 4;
    int crowns[kCrownColours];
    for (int k = 0; k < kCrownColours; ++k) {
        const glm::vec3 green(0.18f + 0.06f * float(k), 0.45f + 0.05f * float(k), 0.15f);
        crowns[k] = s.addMaterial(glassCrowns ? transparent("crown" + std::to_string(k), green, 0.5f)
                                              : opaque("crown" + std::to_string(k), green));
    }
    Node model;
    model.name = "tree";
    const int modelNode = int(s.nodes.size());
    s.nodes.push_back(model);  // placed by the instances, not a root
    auto part = [&](int mesh, int material, const glm::mat4& local) {
        Node n;
        n.local = local;
        n.meshes = {mesh};
        n.materialOverride = material;
        s.addNode(std::move(n), modelNode);
    };
    part(trunkMesh, bark, glm::mat4(1.0f));
    part(crownMesh, -1, glm::translate(glm::mat4(1.0f), {0.0f, 1.55f, 0.0f}));
    part(crownMesh, -1, glm::rotate(glm::translate(glm::mat4(1.0f), {0.35f, 1.25f, 0.2f}), 1.3f, glm::vec3(0, 1, 0)));
    part(crownMesh, -1, glm::rotate(glm::translate(glm::mat4(1.0f), {-0.3f, 1.3f, -0.25f}), 2.6f, glm::vec3(0, 1, 0)));
    const InstanceGrid grid(count, 2.5f);
    for (int i = 0; i < count; ++i) {
        const glm::vec3 at = grid.at(i, 0.0f);
        Node instance;
        instance.name = "tree " + std::to_string(i);
        // Golden-angle turns about the vertical and sizes 0.8..1.2: every instance looks different
        // and all share one impostor per material (the turn and size are above the unit).
        const float size = 0.8f + 0.4f * float((i * 37) % 11) / 10.0f;
        instance.local = glm::scale(glm::rotate(glm::translate(glm::mat4(1.0f), at), glm::radians(137.508f * float(i)),
                                                glm::vec3(0, 1, 0)),
                                    glm::vec3(size));
        instance.children = {modelNode};
        instance.materialOverride = crowns[i % kCrownColours];  // the crowns'; the trunk keeps its bark
        instance.lodUnit = true;
        s.addNode(std::move(instance));
    }
    grid.addGroundAndCamera(s);
    return s;
}

namespace {

Scene makeBuiltinSceneWithoutOptions(const std::string& spec);

constexpr std::string_view kWireframeSuffix = ":wireframe";

}  // namespace

Scene makeBuiltinScene(const std::string& spec) {
    // ":wireframe" after any builtin draws a translucent wireframe over its transparent surfaces.
    if (spec.size() > kWireframeSuffix.size() && spec.ends_with(kWireframeSuffix)) {
        Scene s = makeBuiltinSceneWithoutOptions(spec.substr(0, spec.size() - kWireframeSuffix.size()));
        addWireframes(s);
        s.name += ":wireframe";
        return s;
    }
    return makeBuiltinSceneWithoutOptions(spec);
}

namespace {

Scene makeBuiltinSceneWithoutOptions(const std::string& spec) {
    auto colon = spec.find(':');
    std::string name = spec.substr(0, colon);
    std::string arg = colon == std::string::npos ? "" : spec.substr(colon + 1);
    if (name == "layers") {
        const auto [count, option] = parseCountAndOption(spec, name, arg, 8, 1, 4096, {"textured", "lit", "glass"});
        if (option == "lit" || option == "glass") return makeLitLayersScene(count, option == "glass");
        return makeLayersScene(count, 0.5f, option == "textured");
    }
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
    if (name == "field") {
        const auto [count, option] = parseCountAndOption(spec, name, arg, 100, 1, kFieldMaxInstances, {"transparent"});
        return makeFieldScene(count, option == "transparent");
    }
    if (name == "orchard") {
        const auto [count, option] = parseCountAndOption(spec, name, arg, 1000, 1, kOrchardMaxInstances, {"glass"});
        return makeOrchardScene(count, option == "glass");
    }
    if (name == "default" && arg.empty()) return makeDefaultScene();
    std::string known;
    for (const auto& b : builtinScenes()) known += (known.empty() ? "" : ", ") + b.name;
    throw std::invalid_argument("builtin:" + spec + ": unknown builtin scene (known: " + known + ")");
}

}  // namespace

}  // namespace strata
