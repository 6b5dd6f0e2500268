#include "scene/scene_description.hpp"

#include "io/bounded_read.hpp"
#include "io/printable.hpp"
#include "scene/gltf_loader.hpp"
#include "scene/wireframe.hpp"

#include <nlohmann/json.hpp>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <limits>
#include <map>
#include <optional>
#include <string>

namespace strata {
namespace {

using json = nlohmann::json;

// Internal error holding the part after "<json file>: ".
struct Bad : std::runtime_error {
    using std::runtime_error::runtime_error;
};

[[noreturn]] void fail(const std::string& what) { throw Bad(what); }

// A description is a flat list of objects; nothing legitimate nests deeper than a few levels.
constexpr int kMaxDepth = 16;

void onlyKeys(const json& obj, std::initializer_list<const char*> allowed, const std::string& where) {
    for (const auto& item : obj.items()) {
        bool known = false;
        for (const char* k : allowed) known = known || item.key() == k;
        if (!known) fail(where + "unknown key '" + printable(item.key(), 40) + "'");
    }
}

std::string shortText(double d) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", d);
    return text;
}

// Every number of a description ends up in a float: it is checked as the float it becomes
// (1e308 is a finite double and an infinite float).
float number(const json& v, const std::string& where) {
    if (!v.is_number()) fail(where + ": expected a number");
    double d = v.get<double>();
    if (!std::isfinite(d)) fail(where + ": expected a finite number");
    if (!std::isfinite(float(d))) fail(where + ": " + shortText(d) + " does not fit a float");
    return float(d);
}

template <int N>
glm::vec<N, float> vector(const json& v, const std::string& where) {
    if (!v.is_array() || v.size() != N) fail(where + ": expected an array of " + std::to_string(N) + " numbers");
    glm::vec<N, float> out;
    for (int i = 0; i < N; ++i) out[i] = number(v[std::size_t(i)], where);
    return out;
}

bool finite(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

// A unit vector from `v`, its length taken in double so that components near the float limit
// do not overflow on the way; fails with `zeroMessage` when it is zero.
glm::vec3 unitVector(const glm::vec3& v, const std::string& zeroMessage) {
    glm::dvec3 d(v);
    double length = glm::length(d);
    if (!(length > 1e-6)) fail(zeroMessage);
    return glm::vec3(d / length);
}

glm::vec3 unitRange3(const json& v, const std::string& where) {
    glm::vec3 c = vector<3>(v, where);
    for (int i = 0; i < 3; ++i)
        if (c[i] < 0.0f || c[i] > 1.0f) fail(where + ": components must be in [0, 1]");
    return c;
}

Material parseMaterial(const json& m, const std::string& where) {
    if (!m.is_object()) fail(where + "material: expected an object");
    onlyKeys(m, {"name", "base_color", "alpha", "alpha_mode", "alpha_cutoff", "tau", "albedo", "double_sided", "metallic",
                 "roughness", "emissive", "unlit", "transmission", "ior", "thickness"},
             where + "material: ");
    std::string w = where + "material.";
    Material mat;
    mat.name = "override";
    if (m.contains("name")) {
        if (!m["name"].is_string()) fail(w + "name: expected a string");
        mat.name = m["name"].get<std::string>();
    }
    if (m.contains("base_color")) mat.baseColor = unitRange3(m["base_color"], w + "base_color");
    if (m.contains("alpha")) {
        mat.alpha = number(m["alpha"], w + "alpha");
        if (mat.alpha < 0.0f || mat.alpha > 1.0f) fail(w + "alpha: must be in [0, 1]");
    }
    // A description that lowers alpha means "see through"; requiring BLEND as well is a trap.
    mat.alphaMode = mat.alpha < 1.0f ? AlphaMode::Blend : AlphaMode::Opaque;
    if (m.contains("alpha_mode")) {
        if (!m["alpha_mode"].is_string()) fail(w + "alpha_mode: expected a string");
        std::string mode = m["alpha_mode"].get<std::string>();
        if (mode == "OPAQUE") mat.alphaMode = AlphaMode::Opaque;
        else if (mode == "MASK") mat.alphaMode = AlphaMode::Mask;
        else if (mode == "BLEND") mat.alphaMode = AlphaMode::Blend;
        else fail(w + "alpha_mode: unknown mode '" + printable(mode, 40) + "' (OPAQUE, MASK or BLEND)");
    }
    if (m.contains("alpha_cutoff")) {
        mat.alphaCutoff = number(m["alpha_cutoff"], w + "alpha_cutoff");
        if (mat.alphaCutoff < 0.0f) fail(w + "alpha_cutoff: must be >= 0");
    }
    if (m.contains("tau")) {
        mat.tau = vector<3>(m["tau"], w + "tau");
        mat.volume = true;  // a medium: the volumetric techniques render its inside
        for (int k = 0; k < 3; ++k)
            if (!(mat.tau[k] >= 0.0f && mat.tau[k] <= kMaxTau))
                fail(w + "tau: components must be in [0, " + std::to_string(int(kMaxTau)) + "] per metre");
    }
    if (m.contains("albedo")) mat.albedo = unitRange3(m["albedo"], w + "albedo");
    if (m.contains("double_sided")) {
        if (!m["double_sided"].is_boolean()) fail(w + "double_sided: expected true or false");
        mat.doubleSided = m["double_sided"].get<bool>();
    }
    // The metallic-roughness model (glTF's factors, as the glTF loader reads them).
    for (auto [key, value] : {std::pair<const char*, float*>{"metallic", &mat.metallic}, {"roughness", &mat.roughness},
                              {"transmission", &mat.transmission}})
        if (m.contains(key)) {
            *value = number(m[key], w + key);
            if (!(*value >= 0.0f && *value <= 1.0f)) fail(w + key + ": must be in [0, 1]");
        }
    // KHR_materials_ior and KHR_materials_volume's thickness (the glTF loader's bounds).
    if (m.contains("ior")) {
        mat.ior = number(m["ior"], w + "ior");
        if (!(mat.ior >= 1.0f && mat.ior <= 10.0f)) fail(w + "ior: must be in [1, 10]");
    }
    if (m.contains("thickness")) {
        mat.thickness = number(m["thickness"], w + "thickness");
        if (!(mat.thickness >= 0.0f && mat.thickness <= 1.0e6f)) fail(w + "thickness: must be in [0, 1e6]");
    }
    if (m.contains("emissive")) mat.emissive = unitRange3(m["emissive"], w + "emissive");
    if (m.contains("unlit")) {
        if (!m["unlit"].is_boolean()) fail(w + "unlit: expected true or false");
        mat.unlit = m["unlit"].get<bool>();
    }
    return mat;
}

glm::mat4 objectTransform(const json& o, const std::string& where) {
    glm::mat4 t(1.0f), r(1.0f), s(1.0f);
    if (o.contains("translate")) t = glm::translate(glm::mat4(1.0f), vector<3>(o["translate"], where + "translate"));
    if (o.contains("rotate_deg") && o.contains("rotate_axis_angle"))
        fail(where + "give rotate_deg or rotate_axis_angle, not both");
    if (o.contains("rotate_deg")) {
        glm::vec3 e = glm::radians(vector<3>(o["rotate_deg"], where + "rotate_deg"));
        // X first, then Y, then Z (column vectors: the leftmost applies last).
        r = glm::rotate(glm::mat4(1.0f), e.z, glm::vec3(0, 0, 1)) *
            glm::rotate(glm::mat4(1.0f), e.y, glm::vec3(0, 1, 0)) *
            glm::rotate(glm::mat4(1.0f), e.x, glm::vec3(1, 0, 0));
    }
    if (o.contains("rotate_axis_angle")) {
        glm::vec4 aa = vector<4>(o["rotate_axis_angle"], where + "rotate_axis_angle");
        glm::vec3 axis = unitVector(glm::vec3(aa), where + "rotate_axis_angle: the axis is zero");
        r = glm::rotate(glm::mat4(1.0f), glm::radians(aa.w), axis);
    }
    if (o.contains("scale")) {
        const json& sc = o["scale"];
        glm::vec3 f = sc.is_array() ? vector<3>(sc, where + "scale") : glm::vec3(number(sc, where + "scale"));
        if (f.x == 0.0f || f.y == 0.0f || f.z == 0.0f) fail(where + "scale: must not be zero");
        s = glm::scale(glm::mat4(1.0f), f);
    }
    glm::mat4 m = t * r * s;
    // Each part fits a float, yet their product may not (a huge translate and scale together).
    if (!finite(m)) fail(where + "translate, rotate and scale: the transform overflows a float");
    return m;
}

// Centres a model's bounds `b` at the origin and scales its largest extent to `size`.
glm::mat4 fitTransform(const Bounds& b, float size) {
    glm::vec3 extent = b.max - b.min;
    float largest = std::max(extent.x, std::max(extent.y, extent.z));
    float k = largest > 0.0f ? size / largest : 1.0f;
    return glm::scale(glm::mat4(1.0f), glm::vec3(k)) * glm::translate(glm::mat4(1.0f), -b.center());
}

// Appends `model`'s materials, images, lights, meshes and nodes to `scene`; returns the indices
// of its root nodes there, which every object node placing the model takes as its children.
std::vector<int> appendModel(Scene& scene, Scene&& model) {
    int materialBase = int(scene.materials.size()) - 1;  // model material 0 (default) maps to ours
    int meshBase = int(scene.meshes.size());
    int nodeBase = int(scene.nodes.size());
    const int imageBase = int(scene.images.size());
    const int lightBase = int(scene.lights.size());
    auto material = [&](int m) { return m <= 0 ? m : m + materialBase; };
    for (std::size_t i = 1; i < model.materials.size(); ++i) {
        Material& m = model.materials[i];
        // The model's textures follow its images to their place in the scene's list.
        for (TextureRef* t : {&m.baseColorTexture, &m.metallicRoughnessTexture, &m.normalTexture, &m.occlusionTexture,
                              &m.emissiveTexture})
            if (t->present()) t->image += imageBase;
        scene.materials.push_back(std::move(m));
    }
    for (TextureImage& image : model.images) scene.images.push_back(std::move(image));
    for (Light& light : model.lights) scene.lights.push_back(std::move(light));
    for (Mesh& mesh : model.meshes) {
        mesh.material = material(mesh.material);
        scene.meshes.push_back(std::move(mesh));
    }
    for (Node& node : model.nodes) {
        for (int& c : node.children) c += nodeBase;
        for (int& m : node.meshes) m += meshBase;
        node.materialOverride = material(node.materialOverride);
        if (node.light >= 0) node.light += lightBase;
        scene.nodes.push_back(std::move(node));
    }
    std::vector<int> roots;
    for (int root : model.roots) roots.push_back(root + nodeBase);
    return roots;
}

// A model file already in the scene: its root nodes (shared by every object that places it:
// the node graph is a DAG, scene/scene.hpp's flatten walks each path) and its bounds.
struct PlacedModel {
    std::vector<int> roots;
    Bounds bounds;
    int firstNode = 0, nodeCount = 0;  // the model's nodes in the scene's list
};

// "wireframe": true, false, or {"width": metres, "color": [r,g,b], "alpha": a}, all optional.
std::optional<WireframeStyle> parseWireframe(const json& w) {
    if (w.is_boolean()) return w.get<bool>() ? std::optional<WireframeStyle>(WireframeStyle{}) : std::nullopt;
    if (!w.is_object()) fail("wireframe: expected true, false or an object");
    onlyKeys(w, {"width", "color", "alpha"}, "wireframe: ");
    WireframeStyle style;
    if (w.contains("width")) {
        style.width = number(w["width"], "wireframe.width");
        if (!(style.width > 0.0f)) fail("wireframe.width: must be > 0");
    }
    if (w.contains("color")) style.color = unitRange3(w["color"], "wireframe.color");
    if (w.contains("alpha")) {
        style.alpha = number(w["alpha"], "wireframe.alpha");
        if (style.alpha < 0.0f || style.alpha > 1.0f) fail("wireframe.alpha: must be in [0, 1]");
    }
    return style;
}

void parseCamera(Scene& scene, const json& c) {
    if (!c.is_object()) fail("camera: expected an object");
    onlyKeys(c, {"position", "target", "up", "fov_y_deg"}, "camera: ");
    if (!c.contains("position") || !c.contains("target")) fail("camera: needs position and target");
    glm::vec3 position = vector<3>(c["position"], "camera.position");
    glm::vec3 target = vector<3>(c["target"], "camera.target");
    glm::vec3 up = c.contains("up") ? vector<3>(c["up"], "camera.up") : glm::vec3(0, 1, 0);
    // In double: the difference of two points near the float limit overflows a float.
    glm::dvec3 toTarget = glm::dvec3(target) - glm::dvec3(position);
    if (!(glm::length(toTarget) > 1e-6)) fail("camera: position and target coincide");
    glm::vec3 dir(glm::normalize(toTarget));
    up = unitVector(up, "camera.up: is zero");
    // Looking straight along `up` leaves the roll undefined; pick another up then.
    if (std::abs(glm::dot(dir, up)) > 0.999f) up = std::abs(dir.z) < 0.9f ? glm::vec3(0, 0, 1) : glm::vec3(1, 0, 0);
    CameraPose pose;
    pose.position = position;
    pose.orientation = glm::quatLookAtRH(dir, up);  // maps the camera's -Z onto dir
    if (c.contains("fov_y_deg")) {
        pose.fovYDegrees = number(c["fov_y_deg"], "camera.fov_y_deg");
        if (pose.fovYDegrees <= 0.0f || pose.fovYDegrees >= 180.0f) fail("camera.fov_y_deg: must be in (0, 180)");
    }
    scene.camera = pose;
}

Scene parse(const json& doc, const std::filesystem::path& jsonFile, std::vector<std::string>* warnings) {
    if (!doc.is_object()) fail("expected a JSON object at the top level");
    onlyKeys(doc, {"name", "camera", "light_direction", "background", "objects", "wireframe"}, "");
    Scene scene;
    scene.name = jsonFile.stem().string();
    if (doc.contains("name")) {
        if (!doc["name"].is_string()) fail("name: expected a string");
        scene.name = doc["name"].get<std::string>();
    }
    scene.materials.push_back(Material{});  // index 0 always exists
    if (doc.contains("camera")) parseCamera(scene, doc["camera"]);
    if (doc.contains("light_direction")) {
        scene.lightDirection = unitVector(vector<3>(doc["light_direction"], "light_direction"), "light_direction: is zero");
    }
    if (doc.contains("background")) {
        scene.background = vector<3>(doc["background"], "background");
        if (glm::any(glm::lessThan(scene.background, glm::vec3(0.0f)))) fail("background: must be >= 0");
    }
    if (!doc.contains("objects")) fail("missing field 'objects'");
    const json& objects = doc["objects"];
    if (!objects.is_array() || objects.empty()) fail("objects: expected a non-empty array");
    // A file that several objects place is read once: its meshes, materials and textures are
    // the scene's once, each object a node with its transform and overrides above them.
    std::map<std::filesystem::path, PlacedModel> models;
    // Objects whose overrides are written alike share one material: the renderer draws objects
    // of one mesh and one material together (GpuScene::drawObjects).
    std::map<std::string, int> overrides;

    for (std::size_t i = 0; i < objects.size(); ++i) {
        const json& o = objects[i];
        std::string where = "object " + std::to_string(i) + ": ";
        if (!o.is_object()) fail(where + "expected an object");
        onlyKeys(o, {"model", "name", "fit", "translate", "rotate_deg", "rotate_axis_angle", "scale", "material", "lod_unit"},
                 where);
        if (!o.contains("model")) fail(where + "missing field 'model'");
        if (!o["model"].is_string()) fail(where + "model: expected a string");
        std::filesystem::path model = o["model"].get<std::string>();
        if (model.is_relative()) model = jsonFile.parent_path() / model;

        Node node;
        node.name = model.stem().string();
        if (o.contains("name")) {
            if (!o["name"].is_string()) fail(where + "name: expected a string");
            node.name = o["name"].get<std::string>();
        }
        node.local = objectTransform(o, where);
        std::optional<Material> override;
        if (o.contains("material")) override = parseMaterial(o["material"], where);
        float fit = 0.0f;
        if (o.contains("fit")) {
            fit = number(o["fit"], where + "fit");
            if (fit <= 0.0f) fail(where + "fit: must be > 0");
        }

        std::error_code ec;
        std::filesystem::path key = std::filesystem::weakly_canonical(model, ec);
        if (ec) key = model.lexically_normal();
        auto placed = models.find(key);
        if (placed == models.end()) {
            Scene loaded;
            GltfLoadReport report;
            try {
                loaded = loadGltf(model, report);
            } catch (const LoadError& e) {
                fail("object " + std::to_string(i) + ": " + e.what());
            }
            if (warnings)
                for (const std::string& line : report.warnings)
                    if (std::find(warnings->begin(), warnings->end(), line) == warnings->end()) warnings->push_back(line);
            const Bounds bounds = worldBounds(loaded, flatten(loaded));
            const int firstNode = int(scene.nodes.size());
            std::vector<int> roots = appendModel(scene, std::move(loaded));
            placed = models.emplace(key, PlacedModel{std::move(roots), bounds, firstNode, int(scene.nodes.size()) - firstNode}).first;
        }
        // The unit of level of detail: the whole object (default), each part (false), or the
        // subtrees of the model's nodes of one name (which every placement of the model shares).
        node.lodUnit = true;
        if (o.contains("lod_unit")) {
            const json& unit = o["lod_unit"];
            if (unit.is_boolean()) {
                node.lodUnit = unit.get<bool>();
            } else if (unit.is_string()) {
                node.lodUnit = false;
                const std::string name = unit.get<std::string>();
                int marked = 0;
                for (int n = placed->second.firstNode; n < placed->second.firstNode + placed->second.nodeCount; ++n)
                    if (scene.nodes[std::size_t(n)].name == name) scene.nodes[std::size_t(n)].lodUnit = true, ++marked;
                if (marked == 0) fail(where + "lod_unit: the model has no node named '" + printable(name, 80) + "'");
            } else {
                fail(where + "lod_unit: expected true, false or a node name");
            }
        }
        if (fit > 0.0f) {
            node.local = node.local * fitTransform(placed->second.bounds, fit);
            // A tiny model fitted to a huge size, or a model whose bounds overflow, cannot render.
            if (!finite(node.local)) fail(where + "fit: the transform with the model's bounds overflows a float");
        }
        if (override) {
            const std::string text = o["material"].dump();
            auto shared = overrides.find(text);
            if (shared == overrides.end()) shared = overrides.emplace(text, scene.addMaterial(std::move(*override))).first;
            node.materialOverride = shared->second;
        }
        node.children = placed->second.roots;
        scene.addNode(std::move(node));
    }
    if (doc.contains("wireframe")) {
        if (std::optional<WireframeStyle> style = parseWireframe(doc["wireframe"])) addWireframes(scene, *style);
    }
    return scene;
}

}  // namespace

Scene loadSceneDescription(const std::filesystem::path& jsonFile, std::vector<std::string>* warnings) {
    std::string text;
    try {
        text = readBoundedFile(jsonFile, kSceneDescriptionLimit);
    } catch (const ReadError& e) {
        throw LoadError(e.what());
    }
    return parseSceneDescription(text, jsonFile, warnings);
}

Scene parseSceneDescription(std::string_view text, const std::filesystem::path& jsonFile,
                            std::vector<std::string>* warnings) {
    std::string prefix = printable(jsonFile.string(), 120) + ": ";
    json doc;
    try {
        // Nesting deeper than any description needs is refused while parsing.
        doc = json::parse(text, [](int depth, json::parse_event_t, json&) {
            if (depth > kMaxDepth) throw Bad("JSON nested deeper than " + std::to_string(kMaxDepth) + " levels");
            return true;
        });
    } catch (const Bad& e) {
        throw LoadError(prefix + e.what());
    } catch (const json::exception& e) {
        // nlohmann says "[json.exception.parse_error.101] parse error at line L, column C: ..." or
        // "[json.exception.out_of_range.406] number overflow parsing '1e400'"; it quotes raw input.
        std::string what = e.what();
        auto close = what.find("] ");
        what = close == std::string::npos ? what : what.substr(close + 2);
        throw LoadError(prefix + "JSON " + printable(what, 160));
    }
    try {
        return parse(doc, jsonFile, warnings);
    } catch (const Bad& e) {
        throw LoadError(prefix + e.what());
    } catch (const std::runtime_error& e) {  // flatten() on a loaded model (cannot happen for checked graphs)
        throw LoadError(prefix + e.what());
    }
}

}  // namespace strata
