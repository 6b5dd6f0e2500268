#pragma once
// The layered impostors of a scene: one per mesh that some surface object uses (instances
// share it: the atlas holds normals, the object's material shades them), baked at load with a
// progress line, and the per-object stand-ins for a camera (FrameOptions::standIns).
#include "lod/layered_impostor.hpp"
#include "render/gpu_scene.hpp"
#include "render/stand_in.hpp"

#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

namespace strata::lod {

class ImpostorSet {
public:
    // Bakes now (current GL context). Meshes used only by volume media (GpuScene::objectVolumes())
    // or by no object are not baked. A mesh any transparent object uses gets `transparentPeels`
    // peels (overlap 0); others `settings.peels`. `progress` (null: silent) gets
    // "baking impostors: i/n meshes" lines and a total.
    // With bakeNow false nothing is baked until bakeMeshes asks (LOD bakes only the meshes its
    // selection could use).
    ImpostorSet(const GpuScene& scene, const ImpostorSettings& settings, int transparentPeels = 2,
                std::ostream* progress = nullptr, bool bakeNow = true);

    // Bakes the meshes flagged (indexed like Scene::meshes) that objects can use and that were
    // not tried before; returns how many it tried. A progress line per mesh and a total.
    int bakeMeshes(const std::vector<bool>& meshes);
    bool tried(int mesh) const { return tried_[std::size_t(mesh)]; }

    // The impostor an object draws, or null (volume medium, or its mesh has none: see reasonOf).
    const LayeredImpostor* impostorOf(int objectIndex) const;
    const LayeredImpostor* impostorOfMesh(int mesh) const;
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

    ImpostorMemory bytes() const;          // over all baked meshes
    int bakedMeshes() const;
    double bakeMs() const { return bakeMs_; }
    const ImpostorSettings& settings() const { return settings_; }

private:
    const GpuScene* scene_;
    ImpostorSettings settings_;
    std::vector<std::unique_ptr<LayeredImpostor>> meshImpostors_;  // per mesh, null: not baked
    std::vector<std::string> meshReasons_;
    std::vector<bool> wanted_, transparent_, tried_;  // per mesh
    int transparentPeels_ = 2;
    std::ostream* progress_ = nullptr;
    std::vector<StandInDraw> draws_;                                // per object
    double bakeMs_ = 0.0;
};

}  // namespace strata::lod
