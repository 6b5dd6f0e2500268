#include "lod/lod_units.hpp"

#include <cmath>
#include <map>
#include <utility>

namespace strata::lod {
namespace {

bool finite(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

}  // namespace

LodUnits lodUnits(const std::vector<Object>& objects, const std::vector<bool>& excluded,
                  const std::vector<Bounds>& meshBounds, const std::vector<std::uint64_t>& meshTriangles) {
    LodUnits out;
    out.ofObject.assign(objects.size(), -1);
    std::map<std::pair<int, int>, int> byKey;  // (unit instance, material) -> unit
    auto addPart = [&](LodUnit& unit, int object, const glm::mat4& toRepresentative) {
        const Object& o = objects[std::size_t(object)];
        unit.objects.push_back(object);
        unit.toRepresentative.push_back(toRepresentative);
        unit.bounds.extend(meshBounds[std::size_t(o.mesh)].transformed(toRepresentative));
        unit.triangles += meshTriangles[std::size_t(o.mesh)];
        out.ofObject[std::size_t(object)] = int(&unit - out.units.data());
    };
    for (std::size_t i = 0; i < objects.size(); ++i) {
        if (i < excluded.size() && excluded[i]) continue;
        const Object& o = objects[i];
        const auto [it, added] = byKey.emplace(std::pair{o.unit, o.material}, out.count());
        if (added) {
            out.units.emplace_back();
            addPart(out.units.back(), int(i), glm::mat4(1.0f));
            continue;
        }
        const LodUnit& unit = out.units[std::size_t(it->second)];
        const Object& representative = objects[std::size_t(unit.objects[0])];
        const glm::mat4 toRepresentative = glm::inverse(representative.unitLocal) * o.unitLocal;
        if (finite(toRepresentative)) {
            addPart(out.units[std::size_t(it->second)], int(i), toRepresentative);
        } else {
            out.units.emplace_back();
            addPart(out.units.back(), int(i), glm::mat4(1.0f));
        }
    }
    for (LodUnit& unit : out.units)
        unit.worldBounds = unit.bounds.transformed(objects[std::size_t(unit.objects[0])].world);
    return out;
}

}  // namespace strata::lod
