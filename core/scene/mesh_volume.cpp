#include "scene/mesh_volume.hpp"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <unordered_map>
#include <utility>
#include <vector>

namespace strata {
namespace {

// Maps every vertex to the first vertex within `tolerance` of it (Chebyshev distance), through
// a hash grid of cell size `tolerance`: a vertex's match is in its own cell or a neighbour.
std::vector<std::uint32_t> weldVertices(const std::vector<glm::vec3>& positions, double tolerance) {
    struct CellHash {
        std::size_t operator()(const glm::i64vec3& c) const {
            return std::size_t(c.x * 73856093) ^ std::size_t(c.y * 19349663) ^ std::size_t(c.z * 83492791);
        }
    };
    std::unordered_map<glm::i64vec3, std::vector<std::uint32_t>, CellHash> grid;
    std::vector<std::uint32_t> representative(positions.size());
    auto cellOf = [&](const glm::vec3& p) {
        return glm::i64vec3(std::floor(double(p.x) / tolerance), std::floor(double(p.y) / tolerance),
                            std::floor(double(p.z) / tolerance));
    };
    for (std::uint32_t i = 0; i < positions.size(); ++i) {
        const glm::vec3& p = positions[i];
        const glm::i64vec3 c = cellOf(p);
        std::uint32_t found = i;
        for (int dx = -1; dx <= 1 && found == i; ++dx)
            for (int dy = -1; dy <= 1 && found == i; ++dy)
                for (int dz = -1; dz <= 1 && found == i; ++dz) {
                    auto it = grid.find(c + glm::i64vec3(dx, dy, dz));
                    if (it == grid.end()) continue;
                    for (std::uint32_t j : it->second) {
                        glm::dvec3 d = glm::abs(glm::dvec3(positions[j]) - glm::dvec3(p));
                        if (std::max({d.x, d.y, d.z}) <= tolerance) { found = j; break; }
                    }
                }
        representative[i] = found;
        if (found == i) grid[c].push_back(i);
    }
    return representative;
}

}  // namespace

MeshVolume analyzeMeshVolume(const Mesh& mesh) {
    MeshVolume out;
    const Bounds b = mesh.bounds();
    if (mesh.indices.size() < 12 || b.empty()) {
        out.reason = "fewer than 4 triangles";
        return out;
    }
    for (std::uint32_t i : mesh.indices)
        if (i >= mesh.positions.size()) {
            out.reason = "index past the vertices";
            return out;
        }
    const double diagonal = glm::length(glm::dvec3(b.max) - glm::dvec3(b.min));
    const std::vector<std::uint32_t> weld = weldVertices(mesh.positions, std::max(diagonal * 1e-6, 1e-30));
    // Directed edge (a, b) -> how often a triangle traverses it; degenerate triangles (two welded
    // corners) bound nothing and are skipped, as the rasterizer draws nothing for them.
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
    double volume6 = 0.0;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const std::uint32_t v[3] = {weld[mesh.indices[t]], weld[mesh.indices[t + 1]], weld[mesh.indices[t + 2]]};
        if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) continue;
        for (int k = 0; k < 3; ++k) ++directed[{v[k], v[(k + 1) % 3]}];
        const glm::dvec3 p0(mesh.positions[mesh.indices[t]]), p1(mesh.positions[mesh.indices[t + 1]]),
            p2(mesh.positions[mesh.indices[t + 2]]);
        volume6 += glm::dot(p0, glm::cross(p1, p2));
    }
    for (const auto& [edge, count] : directed) {
        auto reverse = directed.find({edge.second, edge.first});
        const int back = reverse == directed.end() ? 0 : reverse->second;
        if (count == 1 && back == 1) continue;
        if (count == 1 && back == 0) ++out.openEdges;
        else ++out.badEdges;
    }
    out.signedVolume = volume6 / 6.0;
    out.frontFacesOutward = out.signedVolume >= 0.0;
    if (out.openEdges > 0)
        out.reason = std::to_string(out.openEdges) + " open edge" + (out.openEdges == 1 ? "" : "s");
    else if (out.badEdges > 0)
        out.reason = std::to_string(out.badEdges) + " edges shared by more than two triangles or in one direction";
    else if (!(std::abs(out.signedVolume) > 0.0))
        out.reason = "zero enclosed volume";
    out.closed = out.reason.empty();
    return out;
}

double windingNumber(const Mesh& mesh, const glm::dvec3& point) {
    double sum = 0.0;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const glm::dvec3 a = glm::dvec3(mesh.positions[mesh.indices[t]]) - point;
        const glm::dvec3 b = glm::dvec3(mesh.positions[mesh.indices[t + 1]]) - point;
        const glm::dvec3 c = glm::dvec3(mesh.positions[mesh.indices[t + 2]]) - point;
        const double la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
        const double numerator = glm::dot(a, glm::cross(b, c));
        const double denominator = la * lb * lc + glm::dot(a, b) * lc + glm::dot(b, c) * la + glm::dot(c, a) * lb;
        sum += 2.0 * std::atan2(numerator, denominator);
    }
    return sum / (4.0 * glm::pi<double>());
}

bool containsPoint(const Mesh& mesh, const glm::mat4& world, const glm::vec3& point) {
    const glm::dmat4 toObject = glm::inverse(glm::dmat4(world));
    const glm::dvec3 local = glm::dvec3(toObject * glm::dvec4(glm::dvec3(point), 1.0));
    // |w| is 1 inside and 0 outside whatever the orientation; 1/2 splits the two.
    return std::abs(windingNumber(mesh, local)) > 0.5;
}

std::vector<ObjectVolume> classifyVolumes(const Scene& scene, const std::vector<Object>& objects) {
    std::vector<ObjectVolume> out(objects.size());
    std::vector<int> analyzed(scene.meshes.size(), 0);  // meshes analysed once however often placed
    std::vector<MeshVolume> meshes(scene.meshes.size());
    for (std::size_t i = 0; i < objects.size(); ++i) {
        const Object& o = objects[i];
        const Material& m = scene.materials.at(std::size_t(o.material));
        ObjectVolume& v = out[i];
        if (!m.isTransparent()) { v.status = "opaque"; continue; }
        if (!m.volume) { v.status = "surface (the material declares no volume)"; continue; }
        if (!analyzed.at(std::size_t(o.mesh))) {
            meshes[std::size_t(o.mesh)] = analyzeMeshVolume(scene.meshes[std::size_t(o.mesh)]);
            analyzed[std::size_t(o.mesh)] = 1;
        }
        const MeshVolume& mv = meshes[std::size_t(o.mesh)];
        if (!mv.closed) { v.status = "surface (mesh not closed: " + mv.reason + ")"; continue; }
        v.volume = true;
        v.entersThroughFront = mv.frontFacesOutward;
        v.status = "volume";
    }
    return out;
}

}  // namespace strata
