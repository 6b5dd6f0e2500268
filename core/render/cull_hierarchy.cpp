#include "render/cull_hierarchy.hpp"

#include <algorithm>

namespace strata {
namespace {

constexpr int kUnitsPerLeaf = 4;

// A sphere around every sphere of [first, last) (the empty ones skipped): centred on the box of
// their extents, its radius the farthest reach from there.
template <class It, class Get>
auto enclose(It first, It last, Get sphereOf) {
    Bounds box;
    for (It it = first; it != last; ++it) {
        const auto& s = sphereOf(*it);
        if (s.radius >= 0.0f) box.extend(s.centre - glm::vec3(s.radius)), box.extend(s.centre + glm::vec3(s.radius));
    }
    std::decay_t<decltype(sphereOf(*first))> out;
    if (box.empty()) return out;
    out.centre = box.center();
    out.radius = 0.0f;
    for (It it = first; it != last; ++it) {
        const auto& s = sphereOf(*it);
        if (s.radius >= 0.0f) out.radius = std::max(out.radius, glm::length(s.centre - out.centre) + s.radius);
    }
    // Round-off in the sum must not leave a held sphere's edge outside: the hierarchy answers
    // exactly as the per-object test would (a sphere wholly out of a plane holds none inside it).
    out.radius *= 1.0f + 1e-5f;
    return out;
}

}  // namespace

CullHierarchy::CullHierarchy(const std::vector<Object>& objects) {
    objectSpheres_.resize(objects.size());
    for (std::size_t i = 0; i < objects.size(); ++i) {
        const Bounds& b = objects[i].worldBounds;
        if (!b.empty()) objectSpheres_[i] = {b.center(), b.radius()};
        // A unit's objects come one after another in flatten's depth-first order.
        if (units_.empty() || objects[i].unit != objects[std::size_t(units_.back().firstObject)].unit)
            units_.push_back({{}, int(i), 0});
        ++units_.back().objectCount;
    }
    for (Unit& u : units_)
        u.sphere = enclose(objectSpheres_.begin() + u.firstObject, objectSpheres_.begin() + u.firstObject + u.objectCount,
                           [](const Sphere& s) -> const Sphere& { return s; });
    if (!units_.empty()) {
        nodes_.reserve(2 * units_.size() / kUnitsPerLeaf + 2);
        build(0, int(units_.size()));
    }
}

int CullHierarchy::build(int first, int count) {
    const int index = int(nodes_.size());
    nodes_.push_back({});
    const auto begin = units_.begin() + first, end = begin + count;
    const Sphere sphere = enclose(begin, end, [](const Unit& u) -> const Sphere& { return u.sphere; });
    nodes_[std::size_t(index)] = {sphere, first, count, -1, -1};
    if (count <= kUnitsPerLeaf) return index;
    // The median centre along the widest axis of the centres' box.
    Bounds centres;
    for (auto it = begin; it != end; ++it) centres.extend(it->sphere.centre);
    const glm::vec3 extent = centres.max - centres.min;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const auto middle = begin + count / 2;
    std::nth_element(begin, middle, end, [axis](const Unit& a, const Unit& b) { return a.sphere.centre[axis] < b.sphere.centre[axis]; });
    const int left = build(first, count / 2);
    const int right = build(first + count / 2, count - count / 2);
    nodes_[std::size_t(index)].left = left;
    nodes_[std::size_t(index)].right = right;
    return index;
}

void CullHierarchy::setUnits(int first, int count, bool visible, std::vector<char>& out, CullCounts& counts) const {
    for (int u = first; u < first + count; ++u) {
        const Unit& unit = units_[std::size_t(u)];
        std::size_t kept = 0;
        for (int o = unit.firstObject; o < unit.firstObject + unit.objectCount; ++o) {
            // An object without geometry is never kept (Frustum::mayContain's empty bounds).
            const bool in = visible && objectSpheres_[std::size_t(o)].radius >= 0.0f;
            out[std::size_t(o)] = char(in);
            kept += in ? 1 : 0;
        }
        counts.objectsCulled += std::size_t(unit.objectCount) - kept;
        counts.unitsCulled += kept == 0 ? 1 : 0;
    }
}

void CullHierarchy::walk(int index, const Frustum& frustum, std::vector<char>& visible, CullCounts& counts) const {
    const Node& node = nodes_[std::size_t(index)];
    ++counts.spheresTested;
    // Below an empty sphere is no geometry: Frustum::mayContain culls empty bounds too.
    const Frustum::Side side =
        node.sphere.radius < 0.0f ? Frustum::Side::Outside : frustum.classify(node.sphere.centre, node.sphere.radius);
    if (side != Frustum::Side::Straddles) {
        setUnits(node.first, node.count, side == Frustum::Side::Inside, visible, counts);  // untested below
        return;
    }
    if (node.left >= 0) {
        walk(node.left, frustum, visible, counts);
        walk(node.right, frustum, visible, counts);
        return;
    }
    for (int u = node.first; u < node.first + node.count; ++u) {
        const Unit& unit = units_[std::size_t(u)];
        ++counts.spheresTested;
        const Frustum::Side unitSide =
            unit.sphere.radius < 0.0f ? Frustum::Side::Outside : frustum.classify(unit.sphere.centre, unit.sphere.radius);
        if (unitSide != Frustum::Side::Straddles) {
            setUnits(u, 1, unitSide == Frustum::Side::Inside, visible, counts);
            continue;
        }
        bool any = false;
        for (int o = unit.firstObject; o < unit.firstObject + unit.objectCount; ++o) {
            const Sphere& s = objectSpheres_[std::size_t(o)];
            ++counts.spheresTested;
            const bool in = s.radius >= 0.0f && frustum.classify(s.centre, s.radius) != Frustum::Side::Outside;
            visible[std::size_t(o)] = char(in);
            any = any || in;
            counts.objectsCulled += in ? 0 : 1;
        }
        counts.unitsCulled += any ? 0 : 1;
    }
}

CullCounts CullHierarchy::cull(const Frustum& frustum, std::vector<char>& visible) const {
    visible.resize(objectSpheres_.size());  // the walk writes every entry
    CullCounts counts;
    if (!nodes_.empty()) walk(0, frustum, visible, counts);
    return counts;
}

}  // namespace strata
