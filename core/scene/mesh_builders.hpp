#pragma once
// Procedural meshes for the builtin scenes and tests. All are counter-clockwise outward.
#include "scene/scene.hpp"

namespace strata {

// A w x h quad in the z = 0 plane facing +Z, centred on the origin, two triangles.
Mesh makeQuad(float width, float height);
// An axis-aligned box with flat face normals (24 vertices, 12 triangles).
Mesh makeBox(const glm::vec3& min, const glm::vec3& max);
// A UV sphere with smooth normals.
Mesh makeSphere(float radius, int segments = 32, int rings = 16);
// A dense, lumpy, closed blob: an icosahedron whose faces are split into `edgeSegments`^2
// triangles (20 * edgeSegments^2 in all, welded), pushed onto a sphere, displaced by a few
// octaves of bumps and stretched to an ellipsoid (about 1.0 x 0.85 x 0.75 times `radius`), so it
// looks different from every side. Smooth area-weighted normals. The procedural stand-in for a
// scanned model wherever a dense mesh must exist without files (LOD calibration, builtin:field).
// edgeSegments in [1, 256].
Mesh makeBumpyBlob(int edgeSegments, float radius = 1.0f);
// Smooth per-vertex normals: the area-weighted sum of the adjacent faces' normals.
void computeSmoothNormals(Mesh& mesh);

}  // namespace strata
