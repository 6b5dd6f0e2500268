#include "lod/lod_controller.hpp"

#include "lod/lod_cost_cache.hpp"
#include "lod/lod_error.hpp"
#include "lod/view_directions.hpp"
#include "render/frustum.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <ostream>
#include <stdexcept>

namespace strata::lod {
namespace {

// What of the bake the error bound needs (lod_error.hpp); overlap as the bake uses it.
void setShape(ImpostorSummary& summary, const ImpostorSettings& settings) {
    summary.overlap = settings.peels > 1 ? 0.0 : double(settings.overlap);
    summary.apexHalfAngleRadians = apexHalfAngleRadians(double(settings.apexFactor));
}

// Per view, what drawing it costs: the share of the full slice squares its rectangles cover,
// over all peels (so up to `peels`), and the quads drawn (its non-empty slices, and with hole
// filling the hole-closing slices of two neighbours, each neighbour's the mean over the view's
// adjacent pairs). Fixed once baked, so worked out once per mesh.
std::vector<ViewDrawn> viewsDrawn(const LayeredImpostor& impostor, bool fillsHoles, int level) {
    const ImpostorSettings& s = impostor.settings();
    const int slices = impostor.levelSlices(level);
    std::vector<ViewDrawn> views(std::size_t(s.views));
    std::vector<double> holeQuads(std::size_t(s.views), 0.0), pairs(std::size_t(s.views), 0.0);
    if (fillsHoles)
        for (const auto& [v, w] : impostor.adjacency()) {
            for (int local : impostor.holeSlices(v, w, level))
                holeQuads[std::size_t(v)] +=
                    double(impostor.sliceRange(w, local / slices, local % slices, level).second / 6);
            pairs[std::size_t(v)] += 1.0;
        }
    for (int view = 0; view < s.views; ++view) {
        double texels = 0.0, quads = 0.0;
        for (int peel = 0; peel < s.peels; ++peel)
            for (int slice = 0; slice < slices; ++slice) {
                const SliceRect r = impostor.rectangle(view, peel, slice, level);
                if (!r.empty()) texels += double(r.x1 - r.x0 + 1) * double(r.y1 - r.y0 + 1);
                quads += double(impostor.sliceRange(view, peel, slice, level).second / 6);
            }
        ViewDrawn& d = views[std::size_t(view)];
        d.fraction = texels / (double(s.resolution) * s.resolution * slices);
        const std::size_t v = std::size_t(view);
        d.quads = quads + (pairs[v] > 0.0 ? 2.0 * holeQuads[v] / pairs[v] : 0.0);
    }
    return views;
}

}  // namespace

LodController::LodController(const GpuScene& scene, const LodOptions& options, std::ostream* progress)
    : scene_(scene), options_(options), progress_(progress) {
    // The levels only where they may be drawn.
    options_.impostor.mergedLevels = options_.mergedSlices || options_.levelBasePx > 0.0;
    const std::string invalid = options_.impostor.validate();
    if (!invalid.empty()) throw std::invalid_argument("impostor settings: " + invalid);
    keys_ = impostorKeys(scene_);
    const LodUnits& units = keys_.units;
    inputs_.resize(units.units.size());
    // How many objects share each (mesh, material): the batches GpuScene draws instanced.
    std::map<std::pair<int, int>, int> batch;
    for (const Object& o : scene_.objects()) ++batch[{o.mesh, o.material}];
    std::map<int, int> unitsOfImpostor;
    for (std::size_t u = 0; u < units.units.size(); ++u) {
        const LodUnit& unit = units.units[u];
        LodObjectInput& in = inputs_[u];
        in.center = unit.worldBounds.center();
        in.radius = unit.worldBounds.radius();
        in.triangles = unit.triangles;
        in.objects = int(unit.objects.size());
        in.geometryDraws = 0.0;
        for (int object : unit.objects) {
            const Object& o = scene_.objects()[std::size_t(object)];
            in.geometryDraws += 1.0 / double(batch[{o.mesh, o.material}]);
        }
        in.impostor.id = keys_.ofUnit[u];  // units of the same parts in the same places share it
        if (in.impostor.id >= 0) ++unitsOfImpostor[in.impostor.id];
        const Object& representative = scene_.objects()[std::size_t(unit.objects[0])];
        in.transparent = scene_.scene().materials[std::size_t(representative.material)].isTransparent();
        for (int object : unit.objects)
            in.materialNotBaked = in.materialNotBaked ||
                                  (scene_.materialFeatures(object) & kSceneSurfaceDetail & ~kSceneBakedDetail) != 0;
    }
    // The draws k units of one impostor take when they are all stand-ins: one per distinct
    // (nearest view, hole-closing neighbours) among them, at most kDrawsPerView per view.
    for (LodObjectInput& in : inputs_) {
        if (in.impostor.id < 0) continue;
        const double k = double(unitsOfImpostor[in.impostor.id]);
        in.standInDraws = std::min(k, kDrawsPerView * double(options_.impostor.views)) / k;
    }
}

LodController::~LodController() = default;

// Bakes the meshes this frame's selection could draw as impostors and has not tried yet: each
// judged as if baked (view angle 0, kUnbakedDrawnFraction of every slice square drawn), so a scene
// whose objects all stay geometry bakes nothing.
void LodController::bakeCandidates(const LodView& view, const LodCostModel& model) {
    if (!impostors_) {
        impostors_ =
            std::make_unique<ImpostorSet>(scene_, options_.impostor, options_.transparentPeels, progress_, false, &keys_);
        if (!options_.impostorCache.empty()) {
            cache_ = std::make_unique<ImpostorCache>(options_.impostorCache, options_.impostorCacheMaxBytes);
            impostors_->setCache(cache_.get());
        }
    }
    const std::size_t ids = std::size_t(keys_.count());
    std::vector<bool> wanted(ids, false);
    // Per impostor: the geometry time its units would save per frame, and its triangles.
    std::vector<double> saving(ids, 0.0), triangles(ids, 0.0);
    bool any = false;
    for (std::size_t i = 0; i < inputs_.size(); ++i) {
        const int id = keys_.ofUnit[i];
        if (id < 0 || impostors_->tried(id)) continue;
        LodObjectInput guess = inputs_[i];
        guess.hasImpostor = true;
        guess.impostor.slices = options_.impostor.slices;
        guess.impostor.resolution = options_.impostor.resolution;
        setShape(guess.impostor, options_.impostor);
        guess.impostor.viewAngleRadians = 0.0;
        guess.impostor.drawnFraction = kUnbakedDrawnFraction;
        const LodDecision d = selectLodFor(guess, view, model, selectOptions());
        if (!d.impostor) continue;
        wanted[std::size_t(id)] = any = true;
        saving[std::size_t(id)] += std::max(0.0, d.geometryMs - d.impostorMs);
        triangles[std::size_t(id)] = double(inputs_[i].triangles);
    }
    // With an end to the frames, auto bakes only what pays for itself before it (forced
    // impostors bake whatever it costs).
    declined_.resize(ids, 0);
    declinedBakeMs_.resize(ids, 0.0);
    declinedSavingMs_.resize(ids, 0.0);
    std::vector<double> drawsMsOf(ids, 0.0);  // auto's predicted bake of each id, unscaled
    // This selection's frames included: they are drawn with what is baked now.
    const long long framesLeft = options_.plannedFrames > 0 ? options_.plannedFrames - framesDrawn_ : 0;
    if (any && options_.mode == LodMode::Auto && options_.plannedFrames > 0) {
        if (holeFillingPairs_ < 0)
            holeFillingPairs_ = options_.impostor.holeFilling
                                    ? int(adjacentViews(viewDirections(options_.impostor.views)).size())
                                    : 0;
        any = false;
        for (std::size_t id = 0; id < ids; ++id) {
            if (!wanted[id]) continue;
            const int peels = impostors_->transparent(int(id)) ? options_.transparentPeels : options_.impostor.peels;
            const int draws = options_.impostor.views * peels + holeFillingPairs_;
            // An impostor the cache holds is loaded, not baked: it costs next to nothing.
            const bool cached = impostors_->cached(int(id));
            const double drawsMs = cached ? 0.0 : predictedBakeMs(model, triangles[id], draws, options_.impostor.resolution);
            const double bakeMs = bakeScale() * drawsMs;
            const double savedMs = saving[id] * double(std::max(framesLeft, 0LL));
            declined_[id] = savedMs > bakeMs ? 0 : 1;
            declinedBakeMs_[id] = bakeMs;
            declinedSavingMs_[id] = savedMs;
            if (!declined_[id]) {
                any = true;
                drawsMsOf[id] = drawsMs;
                continue;
            }
            wanted[id] = false;
        }
    }
    if (any && options_.impostorMemoryBytes > 0) {
        // Under a memory cap, bake the most useful (geometry time saved per byte) while they fit
        // beside what is held; the vertex buffer is not known before the bake (the cap is
        // enforced again after the selection).
        auto predictedBytes = [&](std::size_t id) { return std::uint64_t(memoryScale_ * double(formulaBytes(id))); };
        std::vector<std::size_t> order;
        for (std::size_t id = 0; id < ids; ++id)
            if (wanted[id]) order.push_back(id);
        std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
            return saving[a] / double(predictedBytes(a)) > saving[b] / double(predictedBytes(b));
        });
        std::uint64_t held = impostors_->bytes().total();
        any = false;
        for (std::size_t id : order) {
            if (held + predictedBytes(id) > options_.impostorMemoryBytes) {
                wanted[id] = false;
                continue;
            }
            held += predictedBytes(id);
            any = true;
        }
    }
    // What the bake-time scale learns from: the bakes made now (loads cost ~0 and predict 0).
    double predictedMs = 0.0;
    for (std::size_t id = 0; id < ids; ++id)
        if (wanted[id]) predictedMs += drawsMsOf[id];
    const double bakedBefore = impostors_->bakeMs();
    const double loadedBefore = cache_ ? cache_->counts().loadMs : 0.0;
    if (!any || impostors_->bake(wanted, options_.bakeBudgetMs) == 0) return;
    // What the formulas leave out (the vertex buffer) is learnt from what was baked, so the next
    // bake under the cap is not one the selection must evict at once.
    for (std::size_t id = 0; id < ids; ++id)
        if (wanted[id] && impostors_->impostorOfId(int(id)))
            memoryScale_ = std::max(memoryScale_, double(impostors_->impostorOfId(int(id))->bytes().total()) /
                                                      double(std::max<std::uint64_t>(formulaBytes(id), 1)));
    for (std::size_t id = 0; id < ids; ++id)
        if (wanted[id] && !impostors_->tried(int(id))) predictedMs -= drawsMsOf[id];  // waits for a later frame
    if (predictedMs > 0.0) {
        measuredBakeMs_ += impostors_->bakeMs() - bakedBefore - ((cache_ ? cache_->counts().loadMs : 0.0) - loadedBefore);
        predictedBakeMs_ += predictedMs;
    }
    viewsDrawn_.resize(std::size_t(keys_.count()));
    for (std::size_t i = 0; i < inputs_.size(); ++i) {
        const LayeredImpostor* impostor = impostors_->impostorOfId(keys_.ofUnit[i]);
        inputs_[i].hasImpostor = impostor != nullptr;
        if (!impostor) continue;
        inputs_[i].impostor.slices = impostor->settings().slices;
        inputs_[i].impostor.resolution = impostor->settings().resolution;
        inputs_[i].impostor.peels = impostor->settings().peels;
        setShape(inputs_[i].impostor, impostor->settings());
        inputs_[i].impostor.bytes = impostor->bytes().total();
        const int levels = std::min(impostor->levels(), 1 + ImpostorSummary::kMaxCoarserLevels);
        inputs_[i].impostor.coarserLevels = levels - 1;
        for (int level = 1; level < levels; ++level)
            inputs_[i].impostor.coarser[std::size_t(level - 1)].slices = impostor->levelSlices(level);
        auto& drawn = viewsDrawn_[std::size_t(keys_.ofUnit[i])];
        if (drawn.empty())
            for (int level = 0; level < levels; ++level)
                drawn.push_back(viewsDrawn(*impostor, !impostors_->transparent(keys_.ofUnit[i]), level));
    }
}

LodBakeDecisions LodController::bakeDecisions() const {
    LodBakeDecisions d;
    for (std::size_t id = 0; id < declined_.size(); ++id) {
        if (!declined_[id] || (impostors_ && impostors_->tried(int(id)))) continue;
        ++d.declined;
        d.declinedBakeMs += declinedBakeMs_[id];
        d.declinedSavingMs += declinedSavingMs_[id];
    }
    return d;
}

const StandIns* LodController::select(const Camera& camera, glm::ivec2 size, int frames) {
    selection_ = {};
    unitSelection_ = {};
    lastEye_ = camera.position;
    if (options_.mode == LodMode::Geometry) {
        // Nothing baked or measured: every object's own triangles, predicted for nobody.
        selection_.objects.assign(scene_.objects().size(), LodDecision{});
        unitSelection_.objects.assign(inputs_.size(), LodDecision{});
        framesDrawn_ += std::max(frames, 0);
        return nullptr;
    }
    ensureCalibrated();
    const LodView view = lodView(camera, size);
    const LodCostModel model = calibration_ ? calibration_->model : LodCostModel{};
    bakeCandidates(view, model);
    updateViewAngles(camera.position);
    unitSelection_ = selectLod(inputs_, view, model, selectOptions());
    if (enforceMemoryCap()) unitSelection_ = selectLod(inputs_, view, model, selectOptions());
    std::vector<int> use(inputs_.size());  // per unit: -1 geometry, else the stand-in's level
    for (std::size_t i = 0; i < use.size(); ++i)
        use[i] = unitSelection_.objects[i].impostor ? unitSelection_.objects[i].level : -1;
    standIns_ = impostors_->drawsFor(camera.position, use);
    // Per object: its unit's decision (a volume medium, in no unit, its own triangles); the totals
    // are the units'.
    selection_.objects.resize(scene_.objects().size());
    for (std::size_t o = 0; o < selection_.objects.size(); ++o) {
        const int unit = keys_.units.ofObject[o];
        selection_.objects[o] = unit >= 0 ? unitSelection_.objects[std::size_t(unit)] : LodDecision{false, LodReason::NoImpostor};
    }
    selection_.impostorObjects = unitSelection_.impostorObjects;
    selection_.impostorsUsed = unitSelection_.impostorsUsed;
    selection_.impostorBytes = unitSelection_.impostorBytes;
    selection_.predictedMs = unitSelection_.predictedMs;
    selection_.geometryOnlyMs = unitSelection_.geometryOnlyMs;
    framesDrawn_ += std::max(frames, 0);
    return selection_.impostorObjects > 0 ? &standIns_ : nullptr;
}

void LodController::ensureCalibrated() {
    if (options_.mode != LodMode::Auto || calibration_) return;
    if (options_.costModel) {
        calibration_ = LodCalibration{};
        calibration_->model = *options_.costModel;
        calibration_->device = "given";
        return;
    }
    // Kept from an earlier run on this device where there is an impostor cache to keep it in.
    const std::filesystem::path kept = options_.impostorCache.empty() ? std::filesystem::path()
                                                                       : options_.impostorCache / kCostModelFile;
    const std::string deviceKey = kept.empty() ? std::string() : currentDeviceKey();
    if (!kept.empty()) {
        if (auto loaded = loadCostModel(kept, deviceKey)) {
            calibration_ = std::move(*loaded);
            calibration_->kept = true;
            if (progress_) *progress_ << "lod: cost model on " << calibration_->device << " kept from an earlier run (" << kept.string() << ")\n";
            return;
        }
    }
    calibration_ = calibrateLodCost();
    if (!kept.empty()) storeCostModel(kept, deviceKey, *calibration_);
    if (progress_)
        *progress_ << "lod: cost model on " << calibration_->device << ": geometry "
                   << calibration_->model.geometryMsPerMegatriangle << " ms/Mtri, impostor "
                   << calibration_->model.impostorMsPerMegapixel << " ms per million layer pixels ("
                   << calibration_->wallMs << " ms)\n";
}

void LodController::updateViewAngles(const glm::vec3& eye) {
    if (!impostors_) return;
    for (std::size_t i = 0; i < inputs_.size(); ++i) {
        if (!inputs_[i].hasImpostor) continue;
        const LayeredImpostor& impostor = *impostors_->impostorOfId(keys_.ofUnit[i]);
        const glm::vec3 local = impostors_->eyeInObject(keys_.units.units[i].objects[0], eye);
        const int nearest = impostor.nearestView(local);
        inputs_[i].impostor.viewAngleRadians = impostor.nearestViewAngle(local);
        const auto& levels = viewsDrawn_[std::size_t(keys_.ofUnit[i])];
        const ViewDrawn& drawn = levels[0][std::size_t(nearest)];
        inputs_[i].impostor.drawnFraction = drawn.fraction;
        inputs_[i].impostor.quads = drawn.quads;
        for (std::size_t level = 1; level < levels.size(); ++level) {
            ImpostorSummary::Level& coarse = inputs_[i].impostor.coarser[level - 1];
            coarse.drawnFraction = levels[level][std::size_t(nearest)].fraction;
            coarse.quads = levels[level][std::size_t(nearest)].quads;
        }
    }
}

LodPreview LodController::previewBounds(const Camera& camera, glm::ivec2 size, const std::vector<double>& boundsPx) {
    LodPreview preview;
    if (options_.mode != LodMode::Auto) return preview;  // no bound to steer
    ensureCalibrated();
    const LodView view = lodView(camera, size);
    const LodCostModel model = calibration_ ? calibration_->model : LodCostModel{};
    updateViewAngles(camera.position);
    // The units the renderer will draw (outside the frustum they cost nothing at any bound); one
    // not baked yet is judged as bakeCandidates judges it: as if baked, seen along a view.
    // The scratch list is a member, reused: a megabyte allocated and freed per frame is given
    // back to the system and faulted in again by whatever the frame allocates next.
    const Frustum frustum(camera.projection(float(size.x) / float(std::max(size.y, 1))) * camera.view());
    std::vector<LodObjectInput>& inputs = previewInputs_;
    inputs.clear();
    for (std::size_t i = 0; i < inputs_.size(); ++i) {
        if (frustum.classify(inputs_[i].center, inputs_[i].radius) == Frustum::Side::Outside) continue;
        LodObjectInput& in = inputs.emplace_back(inputs_[i]);
        const int id = keys_.ofUnit[i];
        // One the bake step declined (it would not pay over the frames planned) stays geometry.
        const bool declined = id >= 0 && std::size_t(id) < declined_.size() && declined_[std::size_t(id)];
        if (in.hasImpostor || id < 0 || declined || (impostors_ && impostors_->tried(id))) continue;
        in.hasImpostor = true;
        in.impostor.slices = options_.impostor.slices;
        in.impostor.resolution = options_.impostor.resolution;
        setShape(in.impostor, options_.impostor);
        in.impostor.viewAngleRadians = 0.0;
        in.impostor.drawnFraction = kUnbakedDrawnFraction;
    }
    const double area = double(size.x) * double(size.y);
    auto discArea = [&](const LodDecision& d) {
        const double px = std::isfinite(d.projectedPx) ? d.projectedPx : 2.0 * double(std::max(size.x, size.y));
        return std::min(0.7853981633974483 * px * px, area);
    };
    // The ladder's first bound is its least: where the levels serve the budget, the raise above
    // it is what a coarser level may add.
    const double levelBase = options_.levelBasePx > 0.0 && !boundsPx.empty() ? boundsPx.front() : 0.0;
    bool first = true;
    for (double bound : boundsPx) {
        LodLevelPreview level;
        level.boundPx = bound;
        // The loss is the impostors' error bounds weighted by their discs, over the larger of the
        // discs' summed area and the image's (overlapping discs share pixels): at most the bound.
        // Each decision is selectLod's (selectLodFor), summed without keeping them.
        double covered = 0.0, weightedError = 0.0;
        for (std::size_t i = 0; i < inputs.size(); ++i) {
            const LodDecision d = selectLodFor(inputs[i], view, model, {LodMode::Auto, bound, levelBase});
            level.predictedMs += d.impostor ? d.impostorMs : d.geometryMs;
            if (d.impostor) level.impostorObjects += inputs[i].objects;
            if (d.impostor) weightedError += d.errorPx * discArea(d);
            covered += discArea(d);
            // What of the prediction scales with the frame's pixels (a zoom divides it by z^2):
            // the impostor's layer pixels, the geometry's covered pixels.
            // An impostor's quad sides shrink as 1 / z (level.sideMs).
            const double sideMs = d.impostor ? model.impostorSideMs(d.layerPixels, d.quads) : 0.0;
            const double fixedMs = d.impostor ? model.impostorMs(0.0, d.quads, inputs[i].standInDraws)
                                              : model.geometryMs(double(inputs[i].triangles), 0.0, inputs[i].drawsForGeometry());
            level.sideMs += sideMs;
            level.pixelMs += std::max(0.0, (d.impostor ? d.impostorMs : d.geometryMs) - fixedMs - sideMs);
        }
        level.lossPx = weightedError / std::max({covered, area, 1.0});
        if (first) preview.coverage = std::min(1.0, covered / std::max(area, 1.0));
        first = false;
        preview.levels.push_back(level);
    }
    return preview;
}

std::uint64_t LodController::formulaBytes(std::size_t id) const {
    const int peels = impostors_->transparent(int(id)) ? options_.transparentPeels : options_.impostor.peels;
    const bool albedo = keys_.albedo[id];
    return impostorImageBytes(options_.impostor.resolution, options_.impostor.views, peels) * (albedo ? 2 : 1) +
           impostorRectangleBytes(options_.impostor.views, peels, options_.impostor.slices);
}

bool LodController::enforceMemoryCap() {
    if (options_.impostorMemoryBytes == 0 || !impostors_) return false;
    std::uint64_t held = impostors_->bytes().total();
    if (held <= options_.impostorMemoryBytes) return false;
    // This frame's use of each impostor: the predicted geometry time its objects save.
    const std::size_t ids = std::size_t(keys_.count());
    std::vector<double> useful(ids, 0.0);
    for (std::size_t i = 0; i < unitSelection_.objects.size(); ++i) {
        const LodDecision& d = unitSelection_.objects[i];
        if (d.impostor && keys_.ofUnit[i] >= 0)
            useful[std::size_t(keys_.ofUnit[i])] += std::max(0.0, d.geometryMs - d.impostorMs) + 1e-9;
    }
    std::vector<std::size_t> order;
    for (std::size_t id = 0; id < ids; ++id)
        if (impostors_->impostorOfId(int(id))) order.push_back(id);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return useful[a] < useful[b]; });
    char why[96];
    std::snprintf(why, sizeof why, "evicted: impostors held more than the memory cap (%.2f MB)",
                  double(options_.impostorMemoryBytes) / 1e6);
    bool evicted = false;
    for (std::size_t id : order) {
        if (held <= options_.impostorMemoryBytes) break;
        held -= impostors_->impostorOfId(int(id))->bytes().total();
        impostors_->evict(int(id), why);
        evicted = true;
    }
    for (std::size_t i = 0; i < inputs_.size(); ++i)
        if (inputs_[i].hasImpostor && !impostors_->impostorOfId(keys_.ofUnit[i])) inputs_[i].hasImpostor = false;
    return evicted;
}

std::string LodController::explainObject(int objectIndex) const {
    if (objectIndex < 0 || std::size_t(objectIndex) >= keys_.units.ofObject.size()) return "";
    const int unit = keys_.units.ofObject[std::size_t(objectIndex)];
    if (unit < 0) return "geometry: a volume medium (no impostor)";
    return explainUnit(unit);
}

std::string LodController::explainUnit(int unit) const {
    const std::size_t i = std::size_t(unit);
    if (i >= unitSelection_.objects.size() || i >= inputs_.size()) return "";
    if (options_.mode == LodMode::Geometry) return "geometry: forced";
    return explain(unitSelection_.objects[i], inputs_[i], selectOptions());
}

}  // namespace strata::lod
