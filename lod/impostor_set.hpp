#pragma once
// The layered impostors of a scene: one per mesh that some surface object uses, shared by its
// instances (the atlas holds normals, the object's material shades them), or, for a material
// whose base colour texture, COLOR_0 or MASK the bake keeps (kSceneBakedDetail), one per mesh
// and material; baked at load with a progress line, and the per-object stand-ins for a camera
// (FrameOptions::standIns).
#include "lod/impostor_cache.hpp"
#include "lod/layered_impostor.hpp"
#include "render/gpu_scene.hpp"
#include "render/stand_in.hpp"

#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace strata::lod {

// Which impostor each object draws, as a dense id: objects share one where they share the mesh
// and what the bake keeps of the material.
struct ImpostorKeys {
    std::vector<int> ofObject;    // per object; -1: none (a volume medium)
    std::vector<int> mesh;        // per impostor
    std::vector<int> bakeObject;  // per impostor: the object whose material its bake keeps, -1: normals only
    int count() const { return int(mesh.size()); }
};
ImpostorKeys impostorKeys(const GpuScene& scene);

class ImpostorSet {
public:
    // Bakes now (current GL context). Meshes used only by volume media (GpuScene::objectVolumes())
    // or by no object are not baked. An impostor any transparent object draws gets
    // `transparentPeels` peels (overlap 0); others `settings.peels`. `progress` (null: silent)
    // gets "baking impostors: i/n" lines and a total.
    // With bakeNow false nothing is baked until bake asks (LOD bakes only the impostors its
    // selection could use).
    ImpostorSet(const GpuScene& scene, const ImpostorSettings& settings, int transparentPeels = 2,
                std::ostream* progress = nullptr, bool bakeNow = true);

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

    // The impostor an object draws, or null (volume medium, or none was baked: see reasonOf).
    const LayeredImpostor* impostorOf(int objectIndex) const;
    const LayeredImpostor* impostorOfId(int id) const;
    // Why an object has no impostor (empty when it has one).
    std::string reasonOf(int objectIndex) const;

    // The eye in the object's space: inverse(world) * eyeWorld.
    glm::vec3 eyeInObject(int objectIndex, const glm::vec3& eyeWorld) const;
    // Object `objectIndex`'s stand-in seen from `eyeWorld`, or null when it has no impostor. Holes
    // are filled for opaque impostors only (a transparent one would composite twice where the
    // hole-filling slices overlap the nearest view's). The pointer stays valid, its contents
    // until the next call for the same object.
    const StandInDraw* drawFor(int objectIndex, const glm::vec3& eyeWorld);
    // Per object (indexed like GpuScene::objects()): the stand-in where useImpostor[i] and the
    // object has one, null elsewhere. useImpostor shorter than the object list counts as false.
    std::vector<const StandInDraw*> drawsFor(const glm::vec3& eyeWorld, const std::vector<bool>& useImpostor);
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
    double bakeMs_ = 0.0;
};

}  // namespace strata::lod
