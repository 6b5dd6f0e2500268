#include "lod/impostor_set.hpp"

#include "render/scene_program.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <string>
#include <ostream>
#include <utility>

namespace strata::lod {

namespace {

bool sameSettings(const ImpostorSettings& a, const ImpostorSettings& b) {
    // As a bake uses them: overlap is 0 with more than one peel.
    const float overlapA = a.peels > 1 ? 0.0f : a.overlap, overlapB = b.peels > 1 ? 0.0f : b.overlap;
    return a.views == b.views && a.resolution == b.resolution && a.slices == b.slices && a.peels == b.peels &&
           overlapA == overlapB && a.apexFactor == b.apexFactor && a.holeFilling == b.holeFilling;
}

}  // namespace

ImpostorKeys impostorKeys(const GpuScene& scene) {
    ImpostorKeys keys;
    const auto& objects = scene.objects();
    const Scene& s = scene.scene();
    std::vector<bool> excluded(objects.size());
    for (std::size_t i = 0; i < objects.size(); ++i) excluded[i] = scene.objectVolumes()[i].volume;
    std::vector<Bounds> meshBounds;
    std::vector<std::uint64_t> meshTriangles;
    for (const Mesh& mesh : s.meshes) meshBounds.push_back(mesh.bounds()), meshTriangles.push_back(mesh.triangleCount());
    keys.units = lodUnits(objects, excluded, meshBounds, meshTriangles);
    keys.ofObject.assign(objects.size(), -1);
    keys.ofUnit.assign(keys.units.units.size(), -1);
    // Units share an impostor where each part is the same mesh in the same place, keeping the same
    // material where the bake keeps part of it: the parts' (mesh, material or -1, placement), as bytes.
    std::map<std::string, int> ids;
    for (std::size_t u = 0; u < keys.units.units.size(); ++u) {
        const LodUnit& unit = keys.units.units[u];
        std::string key;
        bool albedo = false;
        for (std::size_t p = 0; p < unit.objects.size(); ++p) {
            const int object = unit.objects[p];
            const bool baked = (scene.materialFeatures(object) & kSceneBakedDetail) != 0;
            albedo = albedo || baked;
            const int part[2] = {objects[std::size_t(object)].mesh, baked ? objects[std::size_t(object)].material : -1};
            key.append(reinterpret_cast<const char*>(part), sizeof part);
            key.append(reinterpret_cast<const char*>(&unit.toRepresentative[p]), sizeof(glm::mat4));
        }
        const auto [it, added] = ids.emplace(std::move(key), keys.count());
        if (added) {
            keys.unit.push_back(int(u));
            keys.albedo.push_back(albedo);
        }
        keys.ofUnit[u] = it->second;
        for (int object : unit.objects) keys.ofObject[std::size_t(object)] = it->second;
    }
    return keys;
}

ImpostorSet::ImpostorSet(const GpuScene& scene, const ImpostorSettings& settings, int transparentPeels,
                         std::ostream* progress, bool bakeNow, const ImpostorKeys* keys)
    : scene_(&scene), settings_(settings), keys_(keys ? *keys : impostorKeys(scene)), transparentPeels_(transparentPeels),
      progress_(progress) {
    const Scene& s = scene.scene();
    const auto& objects = scene.objects();
    const std::size_t n = std::size_t(keys_.count());
    transparent_.assign(n, false);
    tried_.assign(n, false);
    for (std::size_t i = 0; i < objects.size(); ++i)
        if (keys_.ofObject[i] >= 0 && s.materials[std::size_t(objects[i].material)].isTransparent())
            transparent_[std::size_t(keys_.ofObject[i])] = true;
    impostors_.resize(n);
    reasons_.assign(n, "not baked (no object needed it yet)");
    draws_.resize(objects.size());
    if (bakeNow) bake(std::vector<bool>(n, true));
}

int ImpostorSet::bake(const std::vector<bool>& ids, double budgetMs) {
    const auto start = std::chrono::steady_clock::now();
    int total = 0, done = 0;
    const int loadedBefore = loaded_;
    for (std::size_t k = 0; k < tried_.size() && k < ids.size(); ++k) total += ids[k] && !tried_[k];
    if (total == 0) return 0;
    pending_ = total;
    for (std::size_t k = 0; k < tried_.size() && k < ids.size(); ++k) {
        if (!ids[k] || tried_[k]) continue;
        // Under a budget, one bake at least, then none that would start past it: the rest wait
        // for the next call (their objects draw geometry meanwhile).
        if (budgetMs > 0.0 && done > 0 &&
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() >= budgetMs)
            break;
        tried_[k] = true;
        --pending_;
        ImpostorSettings own = settings_;
        if (transparent_[k]) {
            // Disjoint intervals whatever the peel count: an overlapping slice would blend a
            // surface twice.
            own.peels = transparentPeels_;
            own.overlap = 0.0f;
        }
        const LodUnit& unit = keys_.units.units[std::size_t(keys_.unit[k])];
        std::vector<BakePart> parts;
        for (std::size_t p = 0; p < unit.objects.size(); ++p) {
            const GpuMesh& mesh = scene_->meshOf(unit.objects[p]);
            parts.push_back({mesh.vertexArray.id(), mesh.indexCount, unit.toRepresentative[p], unit.objects[p]});
        }
        ++done;
        const std::uint64_t key = cache_ ? keyOf(int(k)) : 0;
        if (cache_) {
            std::optional<LayeredImpostor> kept = cache_->load(key, settings_.mergedLevels);
            // What was loaded is what this bake would make (a key collision would show here).
            if (kept && !sameSettings(kept->settings(), own)) kept.reset();
            if (kept) {
                impostors_[k] = std::make_unique<LayeredImpostor>(std::move(*kept));
                ++loaded_;
                if (progress_) *progress_ << "baking impostors: " << done << "/" << total << " (from the cache)" << std::endl;
                continue;
            }
        }
        auto impostor = std::make_unique<LayeredImpostor>(parts, unit.bounds, own, keys_.albedo[k] ? scene_ : nullptr);
        if (impostor->valid()) {
            if (cache_) cache_->store(key, *impostor);
            impostors_[k] = std::move(impostor);
        } else {
            reasons_[k] = impostor->reason();
        }
        if (progress_) *progress_ << "baking impostors: " << done << "/" << total << std::endl;
    }
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    bakeMs_ += ms;
    if (progress_) {
        const ImpostorMemory b = bytes();
        char line[256];
        std::snprintf(line, sizeof line,
                      "impostors: %d baked, %d from the cache, in %.0f ms; %d in all, %llu bytes (images %llu, "
                      "rectangles %llu, vertices %llu)",
                      done - (loaded_ - loadedBefore), loaded_ - loadedBefore, ms, bakedImpostors(), (unsigned long long)b.total(), (unsigned long long)b.images,
                      (unsigned long long)b.rectangles, (unsigned long long)b.vertexBuffer);
        *progress_ << line << std::endl;
    }
    return done;
}

void ImpostorSet::evict(int id, const std::string& why) {
    auto& impostor = impostors_[std::size_t(id)];
    if (!impostor) return;
    impostor.reset();
    reasons_[std::size_t(id)] = why;
    ++evicted_;
}

bool ImpostorSet::cached(int id) const {
    if (!cache_ || id < 0 || tried_[std::size_t(id)]) return false;
    return cache_->contains(keyOf(id));
}

std::uint64_t ImpostorSet::keyOf(int id) const {
    // Hashing a mesh (and its texture) every frame an untried impostor is considered would cost
    // more than the frame: each key is computed once.
    if (keyMemo_.size() != tried_.size()) keyMemo_.assign(tried_.size(), std::nullopt);
    std::optional<std::uint64_t>& key = keyMemo_[std::size_t(id)];
    if (!key) {
        ImpostorSettings own = settings_;
        if (transparent_[std::size_t(id)]) own.peels = transparentPeels_, own.overlap = 0.0f;
        const LodUnit& unit = keys_.units.units[std::size_t(keys_.unit[std::size_t(id)])];
        std::vector<ImpostorKeyPart> parts;
        for (std::size_t p = 0; p < unit.objects.size(); ++p) {
            BakeMaterial material;
            if (keys_.albedo[std::size_t(id)]) material = {scene_, unit.objects[p]};
            parts.push_back({scene_->objects()[std::size_t(unit.objects[p])].mesh, unit.toRepresentative[p], material});
        }
        key = impostorKey(scene_->scene(), parts, unit.bounds, own);
    }
    return *key;
}

const LayeredImpostor* ImpostorSet::impostorOfId(int id) const {
    if (id < 0 || std::size_t(id) >= impostors_.size()) return nullptr;
    return impostors_[std::size_t(id)].get();
}

const LayeredImpostor* ImpostorSet::impostorOf(int objectIndex) const {
    if (objectIndex < 0 || std::size_t(objectIndex) >= scene_->objects().size()) return nullptr;
    return impostorOfId(idOf(objectIndex));
}

std::string ImpostorSet::reasonOf(int objectIndex) const {
    if (objectIndex < 0 || std::size_t(objectIndex) >= scene_->objects().size()) return "no such object";
    if (scene_->objectVolumes()[std::size_t(objectIndex)].volume) return "a volume medium";
    if (impostorOf(objectIndex)) return {};
    return reasons_[std::size_t(idOf(objectIndex))];
}

bool ImpostorSet::representative(int objectIndex) const {
    const int unit = keys_.units.ofObject[std::size_t(objectIndex)];
    return unit >= 0 && keys_.units.units[std::size_t(unit)].objects[0] == objectIndex;
}

glm::vec3 ImpostorSet::eyeInObject(int objectIndex, const glm::vec3& eyeWorld) const {
    const int unit = keys_.units.ofObject[std::size_t(objectIndex)];
    if (unit >= 0) objectIndex = keys_.units.units[std::size_t(unit)].objects[0];
    const glm::mat4& world = scene_->objects()[std::size_t(objectIndex)].world;
    return glm::vec3(glm::inverse(world) * glm::vec4(eyeWorld, 1.0f));
}

const StandInDraw* ImpostorSet::drawFor(int objectIndex, const glm::vec3& eyeWorld, int level) {
    const LayeredImpostor* impostor = impostorOf(objectIndex);
    if (!impostor) return nullptr;
    if (!representative(objectIndex)) return &nothing_;
    // Hole-filling slices overlap the nearest view's: a transparent impostor would blend twice.
    const bool fillHoles = !transparent_[std::size_t(idOf(objectIndex))];
    StandInDraw& d = draws_[std::size_t(objectIndex)];
    d = impostor->drawFor(eyeInObject(objectIndex, eyeWorld), fillHoles, std::clamp(level, 0, impostor->levels() - 1));
    d.worldBounds = keys_.units.units[std::size_t(keys_.units.ofObject[std::size_t(objectIndex)])].worldBounds;
    return &d;
}

std::vector<const StandInDraw*> ImpostorSet::drawsFor(const glm::vec3& eyeWorld, const std::vector<int>& levels) {
    std::vector<const StandInDraw*> out(scene_->objects().size(), nullptr);
    for (std::size_t i = 0; i < out.size(); ++i) {
        const int unit = keys_.units.ofObject[i];
        if (unit >= 0 && std::size_t(unit) < levels.size() && levels[std::size_t(unit)] >= 0)
            out[i] = drawFor(int(i), eyeWorld, levels[std::size_t(unit)]);
    }
    return out;
}

float ImpostorSet::nearestViewAngle(int objectIndex, const glm::vec3& eyeWorld) const {
    const LayeredImpostor* impostor = impostorOf(objectIndex);
    return impostor ? impostor->nearestViewAngle(eyeInObject(objectIndex, eyeWorld)) : 0.0f;
}

ImpostorMemory ImpostorSet::bytes() const {
    ImpostorMemory total;
    for (const auto& i : impostors_)
        if (i) total += i->bytes();
    return total;
}

int ImpostorSet::bakedImpostors() const {
    int n = 0;
    for (const auto& i : impostors_) n += i ? 1 : 0;
    return n;
}

}  // namespace strata::lod
