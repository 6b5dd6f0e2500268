#pragma once
// Bounding spheres in a hierarchy over the scene graph's objects, for view-frustum culling (issue
// "the scene graph at scale"). The leaves are the LOD unit instances (Object::unit: a model
// instance's parts, or a lone object), each sphere holding its objects' spheres; the inner nodes
// split their units at the median centre along the widest axis, down to a few units a leaf.
// Each frame walks it from the root: a sphere wholly outside a frustum plane culls everything
// below it untested, one wholly inside keeps everything below untested, and only the spheres that
// straddle a plane are opened, down to the objects of a straddling unit. So a frame's plane tests
// are about the spheres near the frustum's planes, not six per object (the per-object answers
// are still written: the frame's draw lists are per object). The spheres are the objects'
// (centre and half diagonal of the world box), as Frustum::mayContain tests them, so the result
// is the per-object test's up to float rounding in a plane distance (an object that close to a
// plane is outside it by less than a rounding error): the hierarchy skips only tests whose
// answer it knows.
// Built once per scene (objects do not move).
#include "render/frustum.hpp"
#include "scene/scene.hpp"

#include <cstddef>
#include <vector>

namespace strata {

struct CullCounts {
    std::size_t objectsCulled = 0;
    std::size_t unitsCulled = 0;     // unit instances wholly outside (every object of theirs culled)
    std::size_t spheresTested = 0;   // hierarchy spheres and objects classified this frame
};

class CullHierarchy {
public:
    explicit CullHierarchy(const std::vector<Object>& objects);

    // visible[i] for every object i (resized to the object count); counts of what was culled.
    CullCounts cull(const Frustum& frustum, std::vector<char>& visible) const;

    int unitCount() const { return int(units_.size()); }
    std::size_t nodeCount() const { return nodes_.size(); }

private:
    struct Sphere {
        glm::vec3 centre{0.0f};
        float radius = -1.0f;  // < 0: empty (no geometry below)
    };
    struct Unit {
        Sphere sphere;
        int firstObject = 0, objectCount = 0;  // a unit's objects are consecutive (depth-first order)
    };
    struct Node {
        Sphere sphere;
        int first = 0, count = 0;  // the units below: [first, first + count)
        int left = -1, right = -1; // children; -1: a leaf
    };
    int build(int first, int count);
    void walk(int node, const Frustum& frustum, std::vector<char>& visible, CullCounts& counts) const;
    void setUnits(int first, int count, bool visible, std::vector<char>& out, CullCounts& counts) const;

    std::vector<Sphere> objectSpheres_;
    std::vector<Unit> units_;
    std::vector<Node> nodes_;  // nodes_[0] is the root when there is any unit
};

}  // namespace strata
