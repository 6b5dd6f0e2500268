#pragma once
// The layered impostors of a scene: one per LOD unit (lod/lod_units.hpp: the parts of a model
// instance that share a material), shared by every unit with the same parts in the same places
// (the atlas holds normals, the representative's material shades them), where a part's base
// colour texture, COLOR_0 or MASK is kept (kSceneBakedDetail) by material too; baked with a
// progress line, and the per-object stand-ins for a camera (FrameOptions::standIns): the
// representative draws the unit's, its other parts draw nothing.
#include "lod/impostor_cache.hpp"
#include "lod/layered_impostor.hpp"
#include "lod/lod_units.hpp"
#include "render/gpu_scene.hpp"
#include "render/stand_in.hpp"

#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace strata::lod {

// Which impostor each unit draws, as a dense id: units share one where their parts are the same
// meshes in the same places, with the same of the material kept.
struct ImpostorKeys {
    LodUnits units;
    std::vector<int> ofObject;  // per object: its unit's impostor; -1: none (a volume medium)
    std::vector<int> ofUnit;    // per unit
    std::vector<int> unit;      // per impostor: the first unit that draws it (whose parts it bakes)
    std::vector<bool> albedo;   // per impostor: the bake keeps material detail (BakeMaterial)
    int count() const { return int(unit.size()); }
};
ImpostorKeys impostorKeys(const GpuScene& scene);

class ImpostorSet {
public:
    // Bakes now (current GL context). Volume media (GpuScene::objectVolumes()) have no unit and no
    // impostor. An impostor any transparent object draws gets
    // `transparentPeels` peels (overlap 0); others `settings.peels`. `progress` (null: silent)
    // gets "baking impostors: i/n" lines and a total.
    // With bakeNow false nothing is baked until bake asks (LOD bakes only the impostors its
    // selection could use).
    // `keys`: impostorKeys(scene) where the caller has them already (null: worked out here).
    ImpostorSet(const GpuScene& scene, const ImpostorSettings& settings, int transparentPeels = 2,
                std::ostream* progress = nullptr, bool bakeNow = true, const ImpostorKeys* keys = nullptr);

    // Loads from `cache` what it holds and stores what is baked (null: bake everything, keep
    // nothing). The cache must outlive the set.
    void setCache(ImpostorCache* cache) { cache_ = cache; }
    // Whether bake(id) would load instead of baking.
    bool cached(int id) const;
    int loadedImpostors() const { return loaded_; }

    const ImpostorKeys& keys() const { return keys_; }
    int idOf(int objectIndex) const { return keys_.ofObject[std::size_t(objectIndex)]; }
    // Bakes the impostors flagged (indexed by id) that objects draw and that were not tried
    // before; returns how many it tried. A progress line per impostor and a total. With
    // `budgetMs` > 0 it starts no bake once that much time has passed (one bake at least): the
    // others stay untried for a later call, and pendingBakes() says how many.
    int bake(const std::vector<bool>& ids, double budgetMs = 0.0);
    int pendingBakes() const { return pending_; }  // flagged by the last bake() and not reached
    bool tried(int id) const { return tried_[std::size_t(id)]; }
    // Whether a transparent object draws impostor `id` (it gets the transparent peel count).
    bool transparent(int id) const { return transparent_[std::size_t(id)]; }

    // The impostor of an object's unit, or null (volume medium, or none was baked: see reasonOf).
    const LayeredImpostor* impostorOf(int objectIndex) const;
    const LodUnits& units() const { return keys_.units; }
    // Whether the object draws its unit's stand-in (the others of the unit draw nothing in its place).
    bool representative(int objectIndex) const;
    const LayeredImpostor* impostorOfId(int id) const;
    // Why an object has no impostor (empty when it has one).
    std::string reasonOf(int objectIndex) const;

    // The eye in the impostor's space (its unit representative's): inverse(world) * eyeWorld.
    glm::vec3 eyeInObject(int objectIndex, const glm::vec3& eyeWorld) const;
    // Object `objectIndex`'s stand-in seen from `eyeWorld`, or null when it has no impostor: its
    // unit's for the representative, an empty draw (nothing) for the unit's other parts. Holes
    // are filled for opaque impostors only (a transparent one would composite twice where the
    // hole-filling slices overlap the nearest view's). The pointer stays valid, its contents
    // until the next call for the same object. `level`: the impostor's level of merged slices
    // (LayeredImpostor::levels; clamped to those it has).
    const StandInDraw* drawFor(int objectIndex, const glm::vec3& eyeWorld, int level = 0);
    // Per object (indexed like GpuScene::objects()): drawFor at level levels[unit of i] where that
    // is >= 0 and the unit has an impostor, null elsewhere. `levels` is per unit; shorter counts
    // as -1 (geometry).
    std::vector<const StandInDraw*> drawsFor(const glm::vec3& eyeWorld, const std::vector<int>& levels);
    // The view error of an object's impostor (radians), 0 without one.
    float nearestViewAngle(int objectIndex, const glm::vec3& eyeWorld) const;

    ImpostorMemory bytes() const;          // over all baked impostors
    int bakedImpostors() const;
    // Frees impostor `id` (the memory cap, LodOptions::impostorMemoryBytes); its objects draw
    // geometry from then on and reasonOf says `why`. It is not baked again.
    void evict(int id, const std::string& why);
    int evictedImpostors() const { return evicted_; }
    double bakeMs() const { return bakeMs_; }
    const ImpostorSettings& settings() const { return settings_; }

private:
    const GpuScene* scene_;
    ImpostorSettings settings_;
    ImpostorKeys keys_;
    std::vector<std::unique_ptr<LayeredImpostor>> impostors_;  // per id, null: not baked
    std::vector<std::string> reasons_;                         // per id
    std::vector<bool> transparent_, tried_;                    // per id
    int transparentPeels_ = 2;
    std::ostream* progress_ = nullptr;
    std::uint64_t keyOf(int id) const;  // impostorKey of impostor `id` as this set bakes it
    ImpostorCache* cache_ = nullptr;
    mutable std::vector<std::optional<std::uint64_t>> keyMemo_;  // per id
    int loaded_ = 0, evicted_ = 0, pending_ = 0;
    std::vector<StandInDraw> draws_;                                // per object
    StandInDraw nothing_;  // what a unit's other parts draw while it is an impostor
    double bakeMs_ = 0.0;
};

}  // namespace strata::lod
