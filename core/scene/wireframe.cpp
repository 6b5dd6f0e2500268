#include "scene/wireframe.hpp"

#include <algorithm>
#include <cmath>

namespace strata {

Mesh makeWireframeMesh(const Mesh& mesh, const glm::mat4& world, float width) {
    Mesh out;
    out.name = mesh.name + " wireframe";
    out.material = mesh.material;
    auto toWorld = [&](const glm::vec3& p) { return glm::dvec3(world * glm::vec4(p, 1.0f)); };
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const glm::vec3 v[3] = {mesh.positions[mesh.indices[t]], mesh.positions[mesh.indices[t + 1]],
                                mesh.positions[mesh.indices[t + 2]]};
        const glm::dvec3 w[3] = {toWorld(v[0]), toWorld(v[1]), toWorld(v[2])};
        const double doubleArea = glm::length(glm::cross(w[1] - w[0], w[2] - w[0]));
        const glm::vec3 normal = glm::cross(v[1] - v[0], v[2] - v[0]);
        const float normalLength = glm::length(normal);
        if (!(doubleArea > 0.0) || !(normalLength > 0.0f)) continue;  // degenerate: no edges to draw
        const glm::vec3 n = normal / normalLength;
        for (int e = 0; e < 3; ++e) {
            const int i = e, j = (e + 1) % 3, k = (e + 2) % 3;
            const double edge = glm::length(w[j] - w[i]);
            const double height = doubleArea / edge;  // of the opposite vertex above the edge
            const float s = float(std::min(double(width) / height, 1.0 / 3.0));
            const glm::vec3 inner_i = v[i] + s * (v[k] - v[i]), inner_j = v[j] + s * (v[k] - v[j]);
            const auto base = std::uint32_t(out.positions.size());
            for (const glm::vec3& p : {v[i], v[j], inner_j, inner_i}) {
                out.positions.push_back(p);
                out.normals.push_back(n);
            }
            // Wound as the triangle is (counter-clockwise about n).
            out.indices.insert(out.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
        }
    }
    return out;
}

int addWireframes(Scene& scene, const WireframeStyle& style) {
    const std::vector<Object> objects = flatten(scene);
    Material wire;
    wire.name = "wireframe";
    wire.baseColor = style.color;
    wire.alpha = style.alpha;
    wire.alphaMode = AlphaMode::Blend;
    int material = -1;
    std::vector<int> wireRoots;
    for (const Object& o : objects) {
        if (!scene.materials[std::size_t(o.material)].isTransparent()) continue;
        const Mesh& mesh = scene.meshes[std::size_t(o.mesh)];
        float width = style.width;
        if (width <= 0.0f) width = 0.006f * glm::length(o.worldBounds.max - o.worldBounds.min);
        Mesh strips = makeWireframeMesh(mesh, o.world, width);
        if (strips.indices.empty()) continue;
        if (material < 0) material = scene.addMaterial(wire);
        Node node;
        node.name = mesh.name + " wireframe";
        node.local = o.world;  // the surface's own matrix: edge vertices transform exactly as the surface's
        node.meshes = {scene.addMesh(std::move(strips))};
        node.materialOverride = material;
        wireRoots.push_back(scene.addNode(std::move(node)));
    }
    // First in object order: within a tie layer the wireframe composites before its surface.
    std::vector<int> roots = wireRoots;
    for (int r : scene.roots)
        if (std::find(wireRoots.begin(), wireRoots.end(), r) == wireRoots.end()) roots.push_back(r);
    scene.roots = std::move(roots);
    return int(wireRoots.size());
}

}  // namespace strata
