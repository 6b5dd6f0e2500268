#pragma once
// What level of detail decides on and bakes: units, not single meshes (issue "the scene graph at
// scale"). A unit is the parts of one scene-graph unit instance (Object::unit: a scene
// description's object, a named glTF node, or a lone object) that share a material. Its parts are
// baked together into one layered impostor in the space of the first of them, the
// representative, which draws the stand-in in all their places with its material; the other
// parts draw nothing while the unit is an impostor. Splitting an instance by material keeps every
// stand-in shaded exactly as its parts are (metallic, roughness, emission, transmission and
// transparency are per material, and an opaque part and a transparent one go through different
// passes). Pure: no GL.
#include "scene/scene.hpp"

#include <glm/glm.hpp>

#include <vector>

namespace strata::lod {

struct LodUnit {
    std::vector<int> objects;  // flatten order; objects[0] is the representative
    // Per object: its own space -> the representative's (the parts' relative placement, the same
    // for every instance of the unit's subtree).
    std::vector<glm::mat4> toRepresentative;
    Bounds bounds;       // every part's mesh bounds in the representative's space
    Bounds worldBounds;  // `bounds` placed by the representative's world transform
    std::uint64_t triangles = 0;
};

struct LodUnits {
    std::vector<LodUnit> units;
    std::vector<int> ofObject;  // per object: its unit, -1 for an excluded one
    int count() const { return int(units.size()); }
};

// Groups `objects` (flatten's) by (Object::unit, material). `excluded[i]` (a volume medium: no
// impostor) keeps object i out of every unit; a part whose relative placement does not invert
// (a zero scale) becomes a unit of its own. `meshBounds[m]` and `meshTriangles[m]` per mesh.
LodUnits lodUnits(const std::vector<Object>& objects, const std::vector<bool>& excluded,
                  const std::vector<Bounds>& meshBounds, const std::vector<std::uint64_t>& meshTriangles);

}  // namespace strata::lod
