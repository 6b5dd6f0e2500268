#pragma once
// Level of detail per unit (lod/lod_units.hpp: a model instance's parts of one material) for a
// frame (DESIGN's data flow: scene graph -> LOD selection -> ... -> opaque pass -> technique):
// calibrates the cost model on the first frame (auto), bakes a unit's layered impostor the first
// time selection could use it, then each frame decides geometry or impostor per unit
// (lod_select.hpp) and hands the frame the stand-ins (FrameOptions::standIns). Geometry mode
// bakes and measures nothing.
#include "lod/impostor_set.hpp"
#include "lod/lod_cost_model.hpp"
#include "lod/lod_select.hpp"
#include "camera/camera.hpp"
#include "frame/budget_governor.hpp"
#include "render/gpu_scene.hpp"
#include "render/stand_in.hpp"

#include <filesystem>
#include <iosfwd>
#include <memory>
#include <optional>
#include <vector>

namespace strata::lod {

struct LodOptions {
    LodMode mode = LodMode::Auto;
    double maxErrorPx = kDefaultMaxErrorPx;
    ImpostorSettings impostor;      // views, resolution, slices, overlap of every baked mesh
    int transparentPeels = 2;       // peels of a mesh a transparent object uses
    // Frames the caller will draw with this controller (render: 1; bench: its frames and warm-up
    // frames over its techniques); 0: no end (the viewer). With an end, auto bakes an impostor
    // only where the geometry time it saves over the frames left exceeds its predicted bake time
    // (lod_cost_model.hpp's predictedBakeMs).
    long long plannedFrames = 0;
    // Auto's cost model as given, not calibrated on this device (tests that state decisions; a
    // model saved from an earlier calibration).
    std::optional<LodCostModel> costModel;
    // Where baked impostors are kept between runs (impostor_cache.hpp); empty: none.
    std::filesystem::path impostorCache;
    std::uint64_t impostorCacheMaxBytes = ImpostorCache::kDefaultMaxBytes;
    // The most impostor memory held at once (images, rectangles, vertices); 0: no cap. Bakes that
    // would pass it are skipped, most useful first (the geometry time saved per byte); when the
    // held impostors pass it anyway, the least useful this frame are evicted (unused first) and
    // their objects draw geometry.
    std::uint64_t impostorMemoryBytes = 0;
    // Baking time per frame (select call), 0: none. The viewer's: a frame starts no bake past it
    // (one at least), and the objects whose impostor waits draw geometry until it is ready.
    double bakeBudgetMs = 0.0;
    // Auto may draw a stand-in with fewer, merged slices (LayeredImpostor::levels), the cheapest
    // whose error is within the bound. Off by default: a per-object pixel bound does not hold a
    // PSNR, and at the default 4 px every orchard tree drops to 8 slices (builtin:orchard:1000
    // at 640x400: 7.6x faster than geometry at 25 dB, against 3.0x at 32 dB with the baked
    // slices; docs/layered-impostors.md).
    bool mergedSlices = false;
    // The frame budget's LOD lever (LodSelectOptions::levelBasePx): > 0 builds the levels and
    // takes a coarser one only as the bound rises above this, its least value
    // (setBudgetBoundPx; previewBounds takes its ladder's first bound as the least). 0: none.
    double levelBasePx = 0.0;
};

// What auto declines to bake because it would not pay over the frames planned: the impostors
// declined at their last judgement and not baked since, for the summary line and the JSON.
struct LodBakeDecisions {
    int declined = 0;
    double declinedBakeMs = 0.0;   // their predicted bake time, summed
    double declinedSavingMs = 0.0; // the geometry time they would have saved over the frames left
};

// What drawing a baked impostor from one of its views costs (lod_cost_model.hpp's terms).
struct ViewDrawn {
    double fraction = 0.0;  // ImpostorSummary::drawnFraction
    double quads = 0.0;     // ImpostorSummary::quads
};

// Distinct stand-in draws of one impostor per view: a frame's stand-ins of one impostor differ
// by their nearest view and by the hole-closing slices of the two next (LayeredImpostor::drawFor).
// Measured on builtin:orchard:1000 from its default camera: 1,000 stand-ins of one 20-view
// impostor in about 132 draws, 6.6 a view.
inline constexpr double kDrawsPerView = 6.0;

// The share of its full slice squares an impostor not baked yet is judged to draw
// (bakeCandidates, previewBounds; one quad a slice). A slice holds only the surface within its
// depth interval, so its rectangle is a small part of the square. Measured means over the views
// of baked impostors (viewsDrawn), 64 slices: builtin:orchard's crown 0.043 (51 quads) and
// trunk 0.029 (72), builtin:field's blob 0.076 (46), the CAD model's parts 0.009-0.11 (48-114).
// The disc's share (pi/4) used before judged every fill about 10x too dear: once the model
// charged quad sides and pixels at their measured rates, auto declined to bake the orchard's
// trees at 640x400, where they draw in half the geometry's time.
inline constexpr double kUnbakedDrawnFraction = 0.1;

class LodController {
public:
    // Needs a current GL context; bakes and calibrates later, on the first frame that needs it.
    // `progress` (null: silent) gets the bake's and the calibration's lines.
    LodController(const GpuScene& scene, const LodOptions& options, std::ostream* progress = nullptr);
    ~LodController();

    // This frame's stand-ins for `camera` at `size` (the display size: errors are in its
    // pixels); null when every object draws its triangles. Valid until the next call.
    // `frames`: how many frames the caller draws with this selection (counted against
    // LodOptions::plannedFrames).
    const StandIns* select(const Camera& camera, glm::ivec2 size, int frames = 1);

    // What auto would select this frame at each error bound (the frame budget's LOD lever,
    // frame/budget_governor.hpp): predicted time, the impostors' loss and count per bound, and
    // the share of the image the units cover. Units not baked yet count as if baked (as the bake
    // step judges them). Empty levels unless the mode is auto. Bakes nothing; calibrates the
    // cost model when it is not yet.
    LodPreview previewBounds(const Camera& camera, glm::ivec2 size, const std::vector<double>& boundsPx);

    // The last frame's decisions per object (each its unit's; totals over the units) and per
    // LOD unit (lod/lod_units.hpp: units().units[u]).
    const LodSelection& selection() const { return selection_; }
    const LodSelection& unitSelection() const { return unitSelection_; }
    const LodUnits& units() const { return keys_.units; }
    const glm::vec3& lastEye() const { return lastEye_; }         // the last frame's eye, world
    const LodOptions& options() const { return options_; }
    void setMode(LodMode mode) { options_.mode = mode; }
    // The bound as the user sets it (or as it is again once no budget steers it). Where the
    // levels serve the frame budget (LodOptions::levelBasePx > 0) none is drawn at it: the level
    // base follows.
    void setMaxErrorPx(double px) {
        options_.maxErrorPx = px;
        if (options_.levelBasePx > 0.0) options_.levelBasePx = px;
    }
    // The bound a frame budget raised from its least, `leastPx`: the levels (where they serve the
    // budget) may add the raise.
    void setBudgetBoundPx(double px, double leastPx) {
        options_.maxErrorPx = px;
        if (options_.levelBasePx > 0.0) options_.levelBasePx = leastPx;
    }
    // What selection is judged with: the mode, the bound and the budget's level base.
    LodSelectOptions selectOptions() const { return {options_.mode, options_.maxErrorPx, options_.levelBasePx}; }
    const ImpostorSet* impostors() const { return impostors_.get(); }
    const ImpostorCache* cache() const { return cache_.get(); }  // null without one (or before the first bake)
    const std::optional<LodCalibration>& calibration() const { return calibration_; }
    LodBakeDecisions bakeDecisions() const;
    // An object's (its unit's) or a unit's decision explained in one line (the panel's list).
    std::string explainObject(int objectIndex) const;
    std::string explainUnit(int unit) const;

private:
    void bakeCandidates(const LodView& view, const LodCostModel& model);
    void ensureCalibrated();                    // auto: the given model, or one measured now
    void updateViewAngles(const glm::vec3& eye); // each baked unit's nearest view from `eye`

    const GpuScene& scene_;
    LodOptions options_;
    std::ostream* progress_;
    // Evicts the least useful impostors of this frame's selection until the held memory fits
    // options_.impostorMemoryBytes; returns whether any was evicted.
    bool enforceMemoryCap();
    // Impostor `id`'s images and rectangles by the formulas (impostor_memory.hpp), before a bake.
    std::uint64_t formulaBytes(std::size_t id) const;
    double memoryScale_ = 1.0;  // baked bytes over formulaBytes, the largest seen (the vertex buffer)
    std::unique_ptr<ImpostorCache> cache_;  // before impostors_, which points into it
    std::unique_ptr<ImpostorSet> impostors_;
    std::optional<LodCalibration> calibration_;
    std::vector<LodObjectInput> inputs_;  // per LOD unit
    std::vector<LodObjectInput> previewInputs_;  // previewBounds' scratch: the units in view
    LodSelection selection_, unitSelection_;
    StandIns standIns_;
    glm::vec3 lastEye_{0.0f};
    ImpostorKeys keys_;                               // which impostor each object draws
    // Per impostor id: declined at its last judgement, with its predicted bake and saving.
    std::vector<char> declined_;
    std::vector<double> declinedBakeMs_, declinedSavingMs_;
    long long framesDrawn_ = 0;                       // frames drawn with earlier selections
    int holeFillingPairs_ = -1;                       // adjacent view pairs (-1: not counted yet)
    // Measured bake time over predictedBakeMs, summed over the bakes so far (kBakeOverhead
    // before any).
    double measuredBakeMs_ = 0.0, predictedBakeMs_ = 0.0;
    double bakeScale() const { return predictedBakeMs_ > 0.0 ? std::max(1.0, measuredBakeMs_ / predictedBakeMs_) : kBakeOverhead; }
    std::vector<std::vector<std::vector<ViewDrawn>>> viewsDrawn_;  // per impostor id, level, view (viewsDrawn)
};

}  // namespace strata::lod
