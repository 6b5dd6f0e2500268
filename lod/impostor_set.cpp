#include "lod/impostor_set.hpp"

#include <chrono>
#include <cstdio>
#include <ostream>

namespace strata::lod {

ImpostorSet::ImpostorSet(const GpuScene& scene, const ImpostorSettings& settings, int transparentPeels,
                         std::ostream* progress, bool bakeNow)
    : scene_(&scene), settings_(settings), transparentPeels_(transparentPeels), progress_(progress) {
    const Scene& s = scene.scene();
    const auto& objects = scene.objects();
    wanted_.assign(s.meshes.size(), false);
    transparent_.assign(s.meshes.size(), false);
    tried_.assign(s.meshes.size(), false);
    for (std::size_t i = 0; i < objects.size(); ++i) {
        if (scene.objectVolumes()[i].volume) continue;
        const std::size_t m = std::size_t(objects[i].mesh);
        wanted_[m] = true;
        if (s.materials[std::size_t(objects[i].material)].isTransparent()) transparent_[m] = true;
    }
    meshImpostors_.resize(s.meshes.size());
    meshReasons_.assign(s.meshes.size(), "no surface object uses the mesh");
    for (std::size_t m = 0; m < s.meshes.size(); ++m)
        if (wanted_[m]) meshReasons_[m] = "not baked (no object needed it yet)";
    draws_.resize(objects.size());
    if (bakeNow) bakeMeshes(wanted_);
}

int ImpostorSet::bakeMeshes(const std::vector<bool>& meshes) {
    const auto start = std::chrono::steady_clock::now();
    const Scene& s = scene_->scene();
    const auto& objects = scene_->objects();
    int total = 0, done = 0;
    for (std::size_t m = 0; m < wanted_.size() && m < meshes.size(); ++m) total += meshes[m] && wanted_[m] && !tried_[m];
    if (total == 0) return 0;
    for (std::size_t m = 0; m < wanted_.size() && m < meshes.size(); ++m) {
        if (!meshes[m] || !wanted_[m] || tried_[m]) continue;
        tried_[m] = true;
        ImpostorSettings own = settings_;
        if (transparent_[m]) {
            // Disjoint intervals whatever the peel count: an overlapping slice would blend a
            // surface twice.
            own.peels = transparentPeels_;
            own.overlap = 0.0f;
        }
        // Objects share the mesh's vertex array; find one that draws it.
        const GpuMesh* mesh = nullptr;
        for (std::size_t i = 0; i < objects.size() && !mesh; ++i)
            if (std::size_t(objects[i].mesh) == m) mesh = &scene_->meshOf(int(i));
        auto impostor = std::make_unique<LayeredImpostor>(*mesh, s.meshes[m].bounds(), own);
        if (impostor->valid()) meshImpostors_[m] = std::move(impostor);
        else meshReasons_[m] = impostor->reason();
        ++done;
        if (progress_) *progress_ << "baking impostors: " << done << "/" << total << " meshes" << std::endl;
    }
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    bakeMs_ += ms;
    if (progress_) {
        const ImpostorMemory b = bytes();
        char line[256];
        std::snprintf(line, sizeof line,
                      "impostors: %d meshes baked in %.0f ms; %d baked, %llu bytes (images %llu, rectangles %llu, vertices %llu)",
                      done, ms, bakedMeshes(), (unsigned long long)b.total(), (unsigned long long)b.images,
                      (unsigned long long)b.rectangles, (unsigned long long)b.vertexBuffer);
        *progress_ << line << std::endl;
    }
    return done;
}

const LayeredImpostor* ImpostorSet::impostorOfMesh(int mesh) const {
    if (mesh < 0 || std::size_t(mesh) >= meshImpostors_.size()) return nullptr;
    return meshImpostors_[std::size_t(mesh)].get();
}

const LayeredImpostor* ImpostorSet::impostorOf(int objectIndex) const {
    if (objectIndex < 0 || std::size_t(objectIndex) >= scene_->objects().size()) return nullptr;
    if (scene_->objectVolumes()[std::size_t(objectIndex)].volume) return nullptr;
    return impostorOfMesh(scene_->objects()[std::size_t(objectIndex)].mesh);
}

std::string ImpostorSet::reasonOf(int objectIndex) const {
    if (objectIndex < 0 || std::size_t(objectIndex) >= scene_->objects().size()) return "no such object";
    if (scene_->objectVolumes()[std::size_t(objectIndex)].volume) return "a volume medium";
    if (impostorOf(objectIndex)) return {};
    return meshReasons_[std::size_t(scene_->objects()[std::size_t(objectIndex)].mesh)];
}

glm::vec3 ImpostorSet::eyeInObject(int objectIndex, const glm::vec3& eyeWorld) const {
    const glm::mat4& world = scene_->objects()[std::size_t(objectIndex)].world;
    return glm::vec3(glm::inverse(world) * glm::vec4(eyeWorld, 1.0f));
}

const StandInDraw* ImpostorSet::drawFor(int objectIndex, const glm::vec3& eyeWorld) {
    const LayeredImpostor* impostor = impostorOf(objectIndex);
    if (!impostor) return nullptr;
    // Hole-filling slices overlap the nearest view's: a transparent impostor would blend twice.
    const bool fillHoles = !transparent_[std::size_t(scene_->objects()[std::size_t(objectIndex)].mesh)];
    StandInDraw& d = draws_[std::size_t(objectIndex)];
    d = impostor->drawFor(eyeInObject(objectIndex, eyeWorld), fillHoles);
    return &d;
}

std::vector<const StandInDraw*> ImpostorSet::drawsFor(const glm::vec3& eyeWorld, const std::vector<bool>& useImpostor) {
    std::vector<const StandInDraw*> out(scene_->objects().size(), nullptr);
    for (std::size_t i = 0; i < out.size() && i < useImpostor.size(); ++i)
        if (useImpostor[i]) out[i] = drawFor(int(i), eyeWorld);
    return out;
}

float ImpostorSet::nearestViewAngle(int objectIndex, const glm::vec3& eyeWorld) const {
    const LayeredImpostor* impostor = impostorOf(objectIndex);
    return impostor ? impostor->nearestViewAngle(eyeInObject(objectIndex, eyeWorld)) : 0.0f;
}

ImpostorMemory ImpostorSet::bytes() const {
    ImpostorMemory total;
    for (const auto& i : meshImpostors_)
        if (i) total += i->bytes();
    return total;
}

int ImpostorSet::bakedMeshes() const {
    int n = 0;
    for (const auto& i : meshImpostors_) n += i ? 1 : 0;
    return n;
}

}  // namespace strata::lod
