#pragma once
// Procedural scenes whose depth complexity and coplanarity are known by construction:
//   builtin:layers:N     N parallel quads covering the view (depth complexity exactly N), nearest
//                        first in submission order; :lit shaded at alpha 0.5, :glass as coloured
//                        transmissive glass of the same tints (the colour-filter bench pair)
//   builtin:coplanar:K   K coincident full-view quads with different colours (one depth, K fragments)
//   builtin:shells:K[:roundoff]  K coincident transparent spheres (two fragments each per pixel);
//                        with roundoff, copy i is scaled by 1 + i ulps and placed through another
//                        transform: coincident up to round-off, so it must render like the exact one
//   builtin:cubes        three partially overlapping transparent cubes sharing face planes
//   builtin:cubes:separated  the same cubes nudged apart so no faces are coplanar
//   builtin:volumes      intersecting transparent spheres with attenuation tau and albedo
//   builtin:slabs:N      N full-view closed slabs of medium, 0.1 thick (exactly 2N fragments per
//                        pixel): the volumetric paper's Tables 1-2 setup
//   builtin:NAME[:ARG]:wireframe  any of them with a translucent wireframe over its transparent
//                        surfaces, coplanar with them (scene/wireframe.hpp, the paper's Fig. 12)
//   builtin:field:N[:transparent]  N instances (1..1000, default 100) of one dense procedural
//                        mesh (makeBumpyBlob, kFieldMeshTriangles triangles) on a grid with
//                        varied rotations, on an opaque ground, the camera looking over the
//                        field: the layered-impostor LOD bench (issue 11). Opaque instances, or
//                        with transparent alpha 0.5
//   builtin:orchard:N[:glass]  N instances (1..100000, default 1000) of a four-part tree model (a
//                        trunk, three crown blobs sharing a mesh; bark and a crown colour) placed
//                        by instance nodes that are LOD units, over an opaque ground: the scene
//                        graph at scale (shared meshes, unit impostors, culling). glass: the
//                        crowns at alpha 0.5
//   builtin:default      the demo: interpenetrating glass, a decal coplanar with a transparent
//                        panel, a translucent wireframe over its own surface, two intersecting
//                        volumes, dense opaque detail behind (a relief of blocks), a row of models
#include "scene/scene.hpp"

#include <string>
#include <vector>

namespace strata {

struct BuiltinSceneInfo {
    std::string name;      // e.g. "layers"
    std::string argument;  // e.g. "N (1..4096, default 8)"
    std::string description;
};

const std::vector<BuiltinSceneInfo>& builtinScenes();

// `spec` is what follows "builtin:", e.g. "layers:8". Throws std::invalid_argument for an
// unknown name or a bad argument.
Scene makeBuiltinScene(const std::string& spec);

// With `textured`, every layer's colour is its factor times a 64 x 64 white base colour texture
// (trilinear, mipmapped, UVs over the quad): the image is the untextured one's, and the bench's
// difference between the two is what the texture fetch costs each technique.
Scene makeLayersScene(int layers, float alpha = 0.5f, bool textured = false);
// The same layers shaded (roughness 0.5, a light from the upper right): BLEND alpha 0.5, or with
// `glass` coloured transmissive glass (transmission 1, OPAQUE) of the same tints.
Scene makeLitLayersScene(int layers, bool glass);
Scene makeCoplanarScene(int copies, float alpha = 0.5f);
Scene makeShellsScene(int copies, bool roundoff);
Scene makeCubesScene(bool separated);
Scene makeVolumesScene();
Scene makeSlabsScene(int slabs);
Scene makeDefaultScene();
// The field: `count` instances (1..1000) sharing mesh 0 (objects in grid order, nearest row
// first), then the ground (mesh 1) as the last object.
Scene makeFieldScene(int count, bool transparentInstances);
// The field's mesh: makeBumpyBlob(kFieldMeshSegments), 20 * 48^2 triangles.
inline constexpr int kFieldMeshSegments = 48;
inline constexpr int kFieldMeshTriangles = 20 * kFieldMeshSegments * kFieldMeshSegments;  // 46080
inline constexpr int kFieldMaxInstances = 1000;

// The orchard: `count` instance nodes (1..kOrchardMaxInstances, LOD units) over one tree model
// (a trunk, then three crowns: objects 4 i .. 4 i + 3 per instance), then the ground last.
Scene makeOrchardScene(int count, bool glassCrowns);
inline constexpr int kOrchardMaxInstances = 100000;
inline constexpr int kOrchardBlobSegments = 6;  // 720 triangles a crown blob

// A distinct, saturated colour for index i (golden-angle hue steps).
glm::vec3 paletteColor(int i);

}  // namespace strata
