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

}  // namespace strata
