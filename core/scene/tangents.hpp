#pragma once
// Tangents for normal textures where a glTF file gives none (its spec asks for MikkTSpace; this
// is the per-vertex average Lengyel describes, which MikkTSpace refines at shared vertices and
// seams: on a mesh whose UV layout is not mirrored within a vertex's triangles the two agree up
// to that averaging).
#include "scene/scene.hpp"

namespace strata {

// Fills mesh.tangents from the normals and TEXCOORD set `set` (which the mesh must have): xyz
// the direction of increasing u made orthogonal to the normal, w = +1 where the direction of
// increasing v points against cross(normal, tangent) (glTF's v runs down the image, so the
// normal texture's +Y, up the image, is cross(normal, tangent) * w), -1 where the layout is
// mirrored. A vertex whose triangles have no UV area gets any unit tangent orthogonal to its
// normal (a normal map cannot be placed there; it then bends the normal in an arbitrary
// direction rather than producing NaN).
void deriveTangents(Mesh& mesh, int set);

// deriveTangents for every mesh whose material has a normal texture on a TEXCOORD set the mesh
// has, and no tangents. Scene producers call it (the glTF loader, the builtin scenes): a mesh
// without tangents draws without its normal texture on the GPU and the CPU reference alike.
void deriveMissingTangents(Scene& scene);

}  // namespace strata
