#include "scene/tangents.hpp"

#include <cmath>
#include <stdexcept>

namespace strata {
namespace {

// Any unit vector orthogonal to unit `n`.
glm::vec3 orthogonal(const glm::vec3& n) {
    const glm::vec3 axis = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    return glm::normalize(glm::cross(n, axis));
}

}  // namespace

void deriveTangents(Mesh& mesh, int set) {
    if (set < 0 || set > 1 || mesh.texCoords[set].size() != mesh.positions.size() ||
        mesh.normals.size() != mesh.positions.size())
        throw std::logic_error("deriveTangents: mesh '" + mesh.name + "' lacks normals or TEXCOORD_" + std::to_string(set));
    const auto& uv = mesh.texCoords[set];
    std::vector<glm::dvec3> du(mesh.positions.size(), glm::dvec3(0.0)), dv(mesh.positions.size(), glm::dvec3(0.0));
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const std::uint32_t i0 = mesh.indices[t], i1 = mesh.indices[t + 1], i2 = mesh.indices[t + 2];
        const glm::dvec3 e1 = glm::dvec3(mesh.positions[i1]) - glm::dvec3(mesh.positions[i0]);
        const glm::dvec3 e2 = glm::dvec3(mesh.positions[i2]) - glm::dvec3(mesh.positions[i0]);
        const glm::dvec2 d1 = glm::dvec2(uv[i1]) - glm::dvec2(uv[i0]);
        const glm::dvec2 d2 = glm::dvec2(uv[i2]) - glm::dvec2(uv[i0]);
        const double r = d1.x * d2.y - d2.x * d1.y;
        if (!(std::abs(r) > 0.0) || !std::isfinite(r)) continue;
        // dP/du and dP/dv of the triangle, weighted by its area in space (|e1 x e2| / 2) so
        // that a sliver does not outvote its neighbours.
        const glm::dvec3 pu = (e1 * d2.y - e2 * d1.y) / r;
        const glm::dvec3 pv = (e2 * d1.x - e1 * d2.x) / r;
        const double area = glm::length(glm::cross(e1, e2));
        const double lu = glm::length(pu), lv = glm::length(pv);
        if (!(lu > 0.0) || !(lv > 0.0) || !std::isfinite(lu) || !std::isfinite(lv)) continue;
        for (std::uint32_t i : {i0, i1, i2}) {
            du[i] += pu / lu * area;
            dv[i] += pv / lv * area;
        }
    }
    mesh.tangents.resize(mesh.positions.size());
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        const glm::dvec3 n = glm::normalize(glm::dvec3(mesh.normals[i]));
        glm::dvec3 t = du[i] - n * glm::dot(n, du[i]);
        const double len = glm::length(t);
        glm::vec3 tangent = len > 1e-12 && std::isfinite(len) ? glm::vec3(t / len) : orthogonal(glm::vec3(n));
        const double handedness = glm::dot(glm::cross(n, glm::dvec3(tangent)), dv[i]);
        mesh.tangents[i] = glm::vec4(tangent, handedness > 0.0 ? -1.0f : 1.0f);
    }
}

void deriveMissingTangents(Scene& scene) {
    for (Mesh& mesh : scene.meshes) {
        if (mesh.material < 0 || std::size_t(mesh.material) >= scene.materials.size()) continue;
        const TextureRef& normalMap = scene.materials[std::size_t(mesh.material)].normalTexture;
        if (normalMap.present() && !mesh.hasTangents() && (normalMap.texCoord == 0 || normalMap.texCoord == 1) &&
            mesh.hasTexCoords(normalMap.texCoord) && mesh.normals.size() == mesh.positions.size())
            deriveTangents(mesh, normalMap.texCoord);
    }
}

}  // namespace strata
