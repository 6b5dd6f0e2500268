#pragma once
// Per-object level of detail for a frame (DESIGN's data flow: scene graph -> LOD selection ->
// ... -> opaque pass -> technique): calibrates the cost model on the first frame (auto), bakes a
// mesh's layered impostor the first time selection could use it, then each frame decides
// geometry or impostor per object (lod_select.hpp) and hands the frame the stand-ins
// (FrameOptions::standIns). Geometry mode bakes and measures nothing.
#include "lod/impostor_set.hpp"
#include "lod/lod_cost_model.hpp"
#include "lod/lod_select.hpp"
#include "camera/camera.hpp"
#include "render/gpu_scene.hpp"
#include "render/stand_in.hpp"

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
};

class LodController {
public:
    // Needs a current GL context; bakes and calibrates later, on the first frame that needs it.
    // `progress` (null: silent) gets the bake's and the calibration's lines.
    LodController(const GpuScene& scene, const LodOptions& options, std::ostream* progress = nullptr);
    ~LodController();

    // This frame's stand-ins for `camera` at `size` (the display size: errors are in its
    // pixels); null when every object draws its triangles. Valid until the next call.
    const StandIns* select(const Camera& camera, glm::ivec2 size);

    const LodSelection& selection() const { return selection_; }  // the last frame's
    const glm::vec3& lastEye() const { return lastEye_; }         // the last frame's eye, world
    const LodOptions& options() const { return options_; }
    void setMode(LodMode mode) { options_.mode = mode; }
    void setMaxErrorPx(double px) { options_.maxErrorPx = px; }
    const ImpostorSet* impostors() const { return impostors_.get(); }
    const std::optional<LodCalibration>& calibration() const { return calibration_; }
    // An object's decision explained in one line (the panel's list).
    std::string explainObject(int objectIndex) const;

private:
    void bakeCandidates(const LodView& view, const LodCostModel& model);

    const GpuScene& scene_;
    LodOptions options_;
    std::ostream* progress_;
    std::unique_ptr<ImpostorSet> impostors_;
    std::optional<LodCalibration> calibration_;
    std::vector<LodObjectInput> inputs_;
    LodSelection selection_;
    StandIns standIns_;
    glm::vec3 lastEye_{0.0f};
    ImpostorKeys keys_;                               // which impostor each object draws
    std::vector<std::vector<double>> viewFractions_;  // per impostor id, per view (drawnFractions)
};

}  // namespace strata::lod
