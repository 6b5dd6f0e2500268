#pragma once
// A translucent wireframe drawn over its own surfaces, the depth-fighting paper's Fig. 12 (a,
// bottom): every triangle edge becomes a thin strip lying in the triangle's own plane, so the
// wireframe and the surface are coplanar along every edge (up to round-off). Without the
// coplanarity-aware techniques the strips z-fight with the surface; with the tie rule
// (render/depth_order.hpp) the wireframe composites in front, because it comes first in object
// order.
//
// A strip for edge (a, b) of triangle (a, b, c) is the trapezoid a, b, b + s (c - b), a + s (c - a)
// with s = width / h (h: the distance of c from the edge, in world units): affine combinations of
// the triangle's own vertices, inside the triangle, `width` wide in the world. A shared edge gets
// a strip from each of its triangles, so it shows twice as wide as one strip. Scene option:
// `builtin:NAME[:ARG]:wireframe`, and "wireframe" in a scene description (scene_description.hpp).
#include "scene/scene.hpp"

namespace strata {

struct WireframeStyle {
    float width = 0.0f;     // one strip's width in world units; 0: 0.6 % of each object's bounds diagonal
    glm::vec3 color{0.92f, 0.95f, 1.0f};
    float alpha = 0.55f;
};

// The strips of every non-degenerate triangle of `mesh` (3 per triangle, 2 triangles each),
// in the mesh's own space; `world` places the mesh and gives `width` its world meaning. At most a
// third of each triangle's height, so thin triangles are filled rather than overrun.
Mesh makeWireframeMesh(const Mesh& mesh, const glm::mat4& world, float width);

// Adds a wireframe object over every transparent object of `scene`, each placed by the same world
// matrix as its surface and put first in object order (so the tie rule draws it in front).
// Returns how many it added.
int addWireframes(Scene& scene, const WireframeStyle& style = {});

}  // namespace strata
