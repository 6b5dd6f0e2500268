#include "zoom_driver.hpp"

#include "view_app.hpp"

#include "frame/zoom_calibration.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace strata {

ZoomChoices zoomChoicesFrom(const ViewOptions& options) {
    ZoomChoices c;
    c.fixedZoom = options.zoom.fixedZoom();
    c.blur = options.zoom.blur;
    c.maxZoom = options.zoom.maxZoom;
    if (const auto budget = options.zoom.budget()) {
        c.targetMs = float(budget->targetMs);
        c.controller = options.zoom.controllerKind() == ZoomControllerKind::Predictive ? 2 : 1;
    }
    return c;
}

const ZoomCostModel* ZoomDriver::model() const {
    return controller_ && controller_->kind() == ZoomControllerKind::Predictive ? &model_ : nullptr;
}

void ZoomDriver::rebuild(glm::ivec2 displaySize, Technique* technique) {
    controller_.reset();
    built_ = choices_;
    builtSize_ = displaySize;
    builtTechnique_ = technique ? technique->info().id : "";
    if (choices_.controller == 0 || !technique) return;
    ZoomBudget budget;
    budget.targetMs = std::max(0.1, double(choices_.targetMs));
    budget.maxZoom = std::clamp(choices_.maxZoom, 1, 16);
    const ZoomControllerKind kind = choices_.controller == 1 ? ZoomControllerKind::Reactive : ZoomControllerKind::Predictive;
    if (kind == ZoomControllerKind::Predictive) {
        // A few frames of builtin:layers at this size; the window waits for them, so say so.
        const ZoomCalibration c = calibrateZoomCost(*technique, displaySize, budget.maxZoom, [](const std::string& line) {
            std::printf("%s\n", line.c_str());
            std::fflush(stdout);
        });
        model_ = c.model;
        char text[160];
        std::snprintf(text, sizeof text, "calibrated: %.2f ms + %.2f ms/Mpx + %.2f ms/Mfragment (rms %.2f ms)",
                      model_.fixedMs, model_.msPerMegapixel, model_.msPerMegafragment, c.rmsResidualMs);
        status_ = text;
        std::printf("zoom %s\n", text);
        std::fflush(stdout);
    } else {
        status_.clear();
    }
    controller_ = makeZoomController(kind, budget, model_);
}

int ZoomDriver::begin(const GpuScene& scene, const Camera& camera, glm::ivec2 displaySize, Technique* technique,
                      FrameOptions& options, double headDegPerSecond) {
    const bool changed = choices_.controller != built_.controller || choices_.targetMs != built_.targetMs ||
                         choices_.maxZoom != built_.maxZoom || displaySize != builtSize_ ||
                         (technique && technique->info().id != builtTechnique_);
    if (changed) rebuild(displaySize, technique);
    headFloor_ = choices_.followHead ? zoomFloorForHeadSpeed(headDegPerSecond) : 1;
    load_ = FrameLoad{displaySize, 0.0, headFloor_};
    if (controller_) {
        load_.transparentArea = transparentScreenArea(
            scene, camera.projection(float(displaySize.x) / float(displaySize.y)) * camera.view(), displaySize);
        zoom_ = controller_->choose(load_);
        predictedMs_ = controller_->predictedMs();
    } else {
        zoom_ = std::clamp(std::max(choices_.fixedZoom, headFloor_), 1, 16);
        predictedMs_ = std::nan("");
    }
    options.zoom = zoom_;
    options.zoomFilter = choices_.blur ? DeflectFilter::Bilinear : DeflectFilter::Nearest;
    return zoom_;
}

void ZoomDriver::end(const FrameResult& result, Technique* technique) {
    measuredMs_ = result.gpuMs;
    if (controller_ && technique)
        controller_->observe(FrameCost{result.zoom, result.gpuMs, fragmentsRasterized(result.stats), load_});
    zoomHistory_.push(float(result.zoom));
    measuredHistory_.push(float(result.gpuMs));
    predictedHistory_.push(std::isfinite(predictedMs_) ? float(predictedMs_) : 0.0f);
}

void ZoomDriver::printFigures() const {
    std::printf("zoom: %d (%s), frame %.3f ms GPU", zoom_, kZoomControllerNames[std::clamp(built_.controller, 0, 2)],
                measuredMs_);
    if (std::isfinite(predictedMs_)) std::printf(", predicted %.3f ms", predictedMs_);
    std::printf("\n");
}

void drawZoomSection(ZoomDriver& zoom, bool immersive) {
    ZoomChoices& c = zoom.choices();
    ImGui::Combo("zoom control", &c.controller, kZoomControllerNames, 3);
    if (c.controller == 0) {
        ImGui::SliderInt("zoom", &c.fixedZoom, 1, 8);
    } else {
        ImGui::InputFloat("target ms", &c.targetMs, 1.0f, 10.0f, "%.1f");
        c.targetMs = std::clamp(c.targetMs, 0.1f, 10000.0f);
        ImGui::SliderInt("max zoom", &c.maxZoom, 2, 16);
    }
    ImGui::Checkbox("blur when enlarging", &c.blur);
    if (immersive) ImGui::Checkbox("fast head turns raise the zoom", &c.followHead);
    ImGui::Text("zoom %d%s   measured %.2f ms", zoom.zoom(), zoom.headFloor() > 1 ? " (head)" : "", zoom.measuredMs());
    if (std::isfinite(zoom.predictedMs())) {
        ImGui::SameLine();
        ImGui::Text("  predicted %.2f ms", zoom.predictedMs());
    }
    if (!zoom.status().empty()) ImGui::TextWrapped("%s", zoom.status().c_str());
    const float top = std::max({zoom.measuredHistory().max(), zoom.predictedHistory().max(), c.targetMs}) * 1.15f;
    char overlay[64];
    std::snprintf(overlay, sizeof overlay, "measured ms (target %.1f)", c.targetMs);
    const FrameHistory& m = zoom.measuredHistory();
    ImGui::PlotLines("##measured", m.data(), m.count(), m.offset(), overlay, 0.0f, top, ImVec2(-1, 50));
    if (c.controller == 2) {
        const FrameHistory& p = zoom.predictedHistory();
        ImGui::PlotLines("##predicted", p.data(), p.count(), p.offset(), "predicted ms", 0.0f, top, ImVec2(-1, 50));
    }
    const FrameHistory& z = zoom.zoomHistory();
    ImGui::PlotLines("##zoom", z.data(), z.count(), z.offset(), "zoom", 0.0f, 9.0f, ImVec2(-1, 40));
}

}  // namespace strata
