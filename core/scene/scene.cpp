#include "scene/scene.hpp"

#include <cmath>
#include <cstdlib>
#include <string>

#include <stdexcept>

namespace strata {

double defaultDepthTieUlps() {
    static const double ulps = [] {
        const char* env = std::getenv("STRATA_DEBUG_DEPTH_TIE_ULPS");
        if (!env || !*env) return 1024.0;
        char* end = nullptr;
        const double v = std::strtod(env, &end);
        return (end && *end == '\0' && std::isfinite(v) && v >= 0.0) ? v : 1024.0;
    }();
    return ulps;
}

const char* to_string(AlphaMode mode) {
    switch (mode) {
        case AlphaMode::Opaque: return "OPAQUE";
        case AlphaMode::Mask: return "MASK";
        case AlphaMode::Blend: return "BLEND";
    }
    return "?";
}

Bounds Bounds::transformed(const glm::mat4& m) const {
    Bounds out;
    if (empty()) return out;
    for (int i = 0; i < 8; ++i) {
        glm::vec3 corner((i & 1) ? max.x : min.x, (i & 2) ? max.y : min.y, (i & 4) ? max.z : min.z);
        out.extend(glm::vec3(m * glm::vec4(corner, 1.0f)));
    }
    return out;
}

Bounds Mesh::bounds() const {
    Bounds b;
    for (const auto& p : positions) b.extend(p);
    return b;
}

int Scene::addNode(Node n, int parent) {
    nodes.push_back(std::move(n));
    int index = int(nodes.size()) - 1;
    if (parent < 0) roots.push_back(index);
    else nodes[parent].children.push_back(index);
    return index;
}

namespace {

struct Flattener {
    const Scene& scene;
    std::vector<Object> objects;
    std::vector<char> onStack;
    int units = 0;

    // `unit` < 0: no unit node above; else the unit instance and the transform from its root.
    void visit(int nodeIndex, const glm::mat4& parentWorld, int inheritedMaterial, int unit, const glm::mat4& parentUnitLocal) {
        if (nodeIndex < 0 || nodeIndex >= int(scene.nodes.size()))
            throw std::runtime_error("node index " + std::to_string(nodeIndex) + " out of range");
        if (onStack[nodeIndex])
            throw std::runtime_error("node graph has a cycle through node " + std::to_string(nodeIndex));
        onStack[nodeIndex] = 1;
        const Node& node = scene.nodes[nodeIndex];
        glm::mat4 world = parentWorld * node.local;
        glm::mat4 unitLocal = parentUnitLocal * node.local;
        if (unit < 0 && node.lodUnit) {
            unit = units++;
            unitLocal = glm::mat4(1.0f);  // the root's own transform places the instance
        }
        int material = node.materialOverride >= 0 ? node.materialOverride : inheritedMaterial;
        for (int meshIndex : node.meshes) {
            if (meshIndex < 0 || meshIndex >= int(scene.meshes.size()))
                throw std::runtime_error("mesh index " + std::to_string(meshIndex) + " out of range");
            const Mesh& mesh = scene.meshes[meshIndex];
            Object o;
            o.id = int(objects.size());
            o.mesh = meshIndex;
            o.material = material >= 0 ? material : mesh.material;
            if (o.material < 0 || o.material >= int(scene.materials.size()))
                throw std::runtime_error("material index " + std::to_string(o.material) + " out of range");
            o.world = world;
            o.worldBounds = mesh.bounds().transformed(world);
            if (unit >= 0) o.unit = unit, o.unitLocal = unitLocal;
            else o.unit = units++;
            objects.push_back(o);
        }
        for (int child : node.children) visit(child, world, material, unit, unitLocal);
        onStack[nodeIndex] = 0;
    }
};

}  // namespace

std::vector<Object> flatten(const Scene& scene) {
    Flattener f{scene, {}, std::vector<char>(scene.nodes.size(), 0)};
    for (int root : scene.roots) f.visit(root, glm::mat4(1.0f), -1, -1, glm::mat4(1.0f));
    return std::move(f.objects);
}

Bounds worldBounds(const Scene&, const std::vector<Object>& objects) {
    Bounds b;
    for (const auto& o : objects) b.extend(o.worldBounds);
    return b;
}

bool hasTransparency(const Scene& scene, const std::vector<Object>& objects) {
    for (const auto& o : objects)
        if (scene.materials[o.material].isTransparent()) return true;
    return false;
}

glm::vec3 volumeFilterOnEntry(const Material& material, const glm::mat4& world) {
    if (!material.transmissive() || !(material.thickness > 0.0f)) return glm::vec3(1.0f);
    const float scale = std::cbrt(std::abs(glm::determinant(glm::mat3(world))));
    return glm::exp(-material.tau * (material.thickness * scale));
}

void makeFlatNormals(Mesh& mesh) {
    Mesh out;
    const std::size_t n = mesh.indices.size() / 3 * 3;
    out.positions.reserve(n);
    out.normals.reserve(n);
    out.indices.reserve(n);
    for (std::size_t t = 0; t < n; t += 3) {
        glm::vec3 a = mesh.positions[mesh.indices[t]];
        glm::vec3 b = mesh.positions[mesh.indices[t + 1]];
        glm::vec3 c = mesh.positions[mesh.indices[t + 2]];
        glm::vec3 normal = glm::cross(b - a, c - a);
        float len = glm::length(normal);
        normal = len > 0.0f ? normal / len : glm::vec3(0.0f, 0.0f, 1.0f);
        for (std::size_t k = t; k < t + 3; ++k) {
            const std::uint32_t source = mesh.indices[k];
            out.indices.push_back(std::uint32_t(out.positions.size()));
            out.positions.push_back(mesh.positions[source]);
            out.normals.push_back(normal);
            for (int set = 0; set < 2; ++set)
                if (mesh.hasTexCoords(set)) out.texCoords[set].push_back(mesh.texCoords[set][source]);
            if (mesh.hasColors()) out.colors.push_back(mesh.colors[source]);
        }
    }
    mesh.positions = std::move(out.positions);
    mesh.normals = std::move(out.normals);
    mesh.indices = std::move(out.indices);
    for (int set = 0; set < 2; ++set) mesh.texCoords[set] = std::move(out.texCoords[set]);
    mesh.colors = std::move(out.colors);
    // glTF 3.7.2.1: with computed flat normals, a file's tangents must be ignored (they were
    // made for normals that are not there); scene/tangents.hpp derives new ones where needed.
    mesh.tangents.clear();
}

glm::mat3 TextureTransform::matrix() const {
    const float c = std::cos(rotation), s = std::sin(rotation);
    // T * R * S, column by column. R takes (1, 0) to (c, -s): "counter-clockwise in UV space"
    // with v pointing down the image, what the Khronos TextureTransformTest asset checks (its
    // rotation quad's arrow reaches the green marker; the opposite sign reaches the red one, which
    // an early draft's matrix, (c, s) in the first column, gives).
    const glm::mat3 t(1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, offset.x, offset.y, 1.0f);
    const glm::mat3 r(c, -s, 0.0f, s, c, 0.0f, 0.0f, 0.0f, 1.0f);
    const glm::mat3 sc(scale.x, 0.0f, 0.0f, 0.0f, scale.y, 0.0f, 0.0f, 0.0f, 1.0f);
    return t * r * sc;
}

}  // namespace strata
