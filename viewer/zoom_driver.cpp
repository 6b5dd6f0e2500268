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
    c.lodBasePx = float(options.lod.options().maxErrorPx);
    if (const auto budget = options.zoom.budget()) {
        c.targetMs = float(budget->targetMs);
        c.controller = options.zoom.controllerKind() == ZoomControllerKind::Predictive ? 2 : 1;
        const BudgetLevers levers = options.zoom.levers(options.lod.options().mode);
        c.levers = levers.zoom && levers.lod ? 2 : levers.lod ? 1 : 0;
    }
    return c;
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
    const BudgetLevers levers{choices_.levers != 1, choices_.levers != 0};
    model_ = ZoomCostModel{};
    if (budgetNeedsCalibration(kind, levers)) {
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
    controller_ = std::make_unique<BudgetGovernor>(budget, levers, kind, model_);
}

int ZoomDriver::begin(const GpuScene& scene, const Camera& camera, glm::ivec2 displaySize, Technique* technique,
                      FrameOptions& options, double headDegPerSecond, lod::LodController* lod) {
    const bool changed = choices_.controller != built_.controller || choices_.targetMs != built_.targetMs ||
                         choices_.maxZoom != built_.maxZoom || choices_.levers != built_.levers ||
                         displaySize != builtSize_ || (technique && technique->info().id != builtTechnique_);
    if (changed) rebuild(displaySize, technique);
    headFloor_ = choices_.followHead ? zoomFloorForHeadSpeed(headDegPerSecond) : 1;
    load_ = GovernorLoad{FrameLoad{displaySize, 0.0, headFloor_}, {}};
    lodBoundPx_ = 0.0;
    lossPx_ = 0.0;
    if (controller_) {
        load_.zoom.transparentArea = transparentScreenArea(
            scene, camera.projection(float(displaySize.x) / float(displaySize.y)) * camera.view(), displaySize);
        // The LOD lever steers auto's bound; in another mode it has nothing to steer this frame.
        const LodLadder ladder{std::max(0.01, double(choices_.lodBasePx)), 4};
        if (controller_->levers().lod && lod) load_.lod = lod->previewBounds(camera, displaySize, ladder.bounds());
        const GovernorChoice choice = controller_->choose(load_);
        zoom_ = choice.zoom;
        predictedMs_ = choice.predictedMs;
        lossPx_ = choice.lossPx;
        if (!load_.lod.levels.empty()) {
            // The bound the user set, kept for when the budget stops steering it.
            if (!steeredBound_) userBoundPx_ = lod->options().maxErrorPx;
            lodBoundPx_ = ladder.bound(choice.lodLevel);
            lod->setBudgetBoundPx(lodBoundPx_, ladder.bound(0));
        }
    } else {
        zoom_ = std::clamp(std::max(choices_.fixedZoom, headFloor_), 1, 16);
        predictedMs_ = std::nan("");
    }
    // The budget stopped steering the bound (another lever, no budget): the user's is auto's again.
    if (lod && steeredBound_ && lodBoundPx_ == 0.0) lod->setMaxErrorPx(userBoundPx_);
    steeredBound_ = lodBoundPx_ > 0.0;
    options.zoom = zoom_;
    options.zoomFilter = choices_.blur ? DeflectFilter::Bilinear : DeflectFilter::Nearest;
    return zoom_;
}

void ZoomDriver::end(const FrameResult& result, Technique* technique) {
    measuredMs_ = result.gpuMs;
    if (controller_ && technique)
        controller_->observe(FrameCost{result.zoom, result.gpuMs, fragmentsRasterized(result.stats), load_.zoom});
    zoomHistory_.push(float(result.zoom));
    measuredHistory_.push(float(result.gpuMs));
    predictedHistory_.push(std::isfinite(predictedMs_) ? float(predictedMs_) : 0.0f);
    boundHistory_.push(float(lodBoundPx_));
}

void ZoomDriver::printFigures() const {
    std::printf("zoom: %d (%s", zoom_, kZoomControllerNames[std::clamp(built_.controller, 0, 2)]);
    if (controller_) std::printf(", levers %s", to_string(controller_->levers()).c_str());
    std::printf("), frame %.3f ms GPU", measuredMs_);
    if (std::isfinite(predictedMs_)) std::printf(", predicted %.3f ms", predictedMs_);
    if (lodBoundPx_ > 0.0) std::printf(", lod bound %.2f px, loss %.3f px", lodBoundPx_, lossPx_);
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
        ImGui::Combo("budget levers", &c.levers, kBudgetLeverNames, 3);
        if (c.levers != 0) {
            ImGui::SliderFloat("least lod bound px", &c.lodBasePx, 0.25f, 16.0f, "%.2f", ImGuiSliderFlags_Logarithmic);
            if (ImGui::IsItemHovered())
                ImGui::SetTooltip("the budget picks the LOD error bound among this, 2x, 4x and 8x (auto LOD only)");
        }
    }
    ImGui::Checkbox("blur when enlarging", &c.blur);
    if (immersive) ImGui::Checkbox("fast head turns raise the zoom", &c.followHead);
    ImGui::Text("zoom %d%s   measured %.2f ms", zoom.zoom(), zoom.headFloor() > 1 ? " (head)" : "", zoom.measuredMs());
    if (zoom.lodBoundPx() > 0.0) {
        ImGui::Text("lod bound %.2f px   loss %.3f px", zoom.lodBoundPx(), zoom.lossPx());
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("the least loss predicted (or measured) to fit the target; loss: zoom's (z-1)/2 px over the\n"
                              "covered share, plus the impostors' error bounds over their areas (frame/budget_governor.hpp)");
    }
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
    if (c.controller != 0 && c.levers != 0) {
        const FrameHistory& b = zoom.boundHistory();
        ImGui::PlotLines("##bound", b.data(), b.count(), b.offset(), "lod bound px", 0.0f,
                         std::max(b.max(), 8.0f * c.lodBasePx) * 1.1f, ImVec2(-1, 40));
    }
}

}  // namespace strata
