#pragma once
// Whether a mesh bounds a volume, and whether a point lies inside it: what the volumetric
// techniques (ll-volume, abuffer-volume) and the CPU reference need to treat a transparent
// object as a participating medium rather than a thin surface.
//
// A mesh bounds a volume when, after welding vertices closer than a tolerance (builders and
// exporters duplicate seam and pole vertices, rounded differently), every edge is shared by
// exactly two triangles that traverse it in opposite directions: closed and consistently
// oriented. Its signed volume then says whether the counter-clockwise (front) faces point out
// (entering through a front face) or in.
#include "scene/scene.hpp"

#include <glm/glm.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace strata {

struct MeshVolume {
    bool closed = false;           // closed and consistently oriented after welding
    bool frontFacesOutward = true; // signed volume > 0: a ray enters through a front face
    double signedVolume = 0.0;     // object space
    std::size_t openEdges = 0;     // edges used once (holes, borders)
    std::size_t badEdges = 0;      // edges used more than twice, or twice in one direction
    std::string reason;            // why the mesh is not a volume; empty when closed
};

// Welds positions within 1e-6 of the mesh's bounding-box diagonal, then checks every edge.
MeshVolume analyzeMeshVolume(const Mesh& mesh);

// The generalised winding number of the closed mesh around `point` (object space): the sum of
// the solid angles of its triangles over 4 pi (Van Oosterom and Strackee). About +1 inside an
// outward-oriented mesh, -1 inside an inward one, 0 outside; robust to round-off, and defined
// without choosing a ray. A point on the surface gives about 1/2.
double windingNumber(const Mesh& mesh, const glm::dvec3& point);

// True when `point` (world space) lies inside the closed mesh of `object` placed by `world`.
bool containsPoint(const Mesh& mesh, const glm::mat4& world, const glm::vec3& point);

// What a volumetric technique makes of one object.
struct ObjectVolume {
    bool volume = false;            // transparent, Material::volume, closed mesh
    // Object space: the ray enters through counter-clockwise (front) faces. A world with a
    // negative determinant mirrors the winding on screen; the GPU accounts for that itself.
    bool entersThroughFront = true;
    std::string status;             // "volume", or why the object is drawn as a surface
};

// One entry per object, indexed like `objects`.
std::vector<ObjectVolume> classifyVolumes(const Scene& scene, const std::vector<Object>& objects);

}  // namespace strata
