#include "immersive_panel.hpp"
#include "lod_panel.hpp"
#include "zoom_driver.hpp"

#include "panel_widgets.hpp"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

namespace strata {
namespace {

const ImVec4 kSelectedColour{1.0f, 0.85f, 0.3f, 1.0f};

// A combo over `names` that sets `index` to the one picked.
void chooseByName(const char* label, const std::vector<std::string>& names, int& index) {
    ImGui::SetNextItemWidth(160.0f);
    if (ImGui::BeginCombo(label, names[std::size_t(index)].c_str())) {
        for (std::size_t i = 0; i < names.size(); ++i)
            if (ImGui::Selectable(names[i].c_str(), int(i) == index)) index = int(i);
        ImGui::EndCombo();
    }
}

void drawHeadTracking(const ImmersivePanelState& state, ImmersiveChoices& choices, ImmersiveRequests& requests) {
    const std::size_t deflections = state.deflections.size();
    auto historyOf = [&](std::size_t predictor, std::size_t deflection) -> const FrameHistory& {
        return (*state.errorHistory)[predictor * deflections + deflection];
    };
    ImGui::TextWrapped("trace %s", state.traceName.c_str());
    ImGui::TextWrapped("truth: %s", state.truthLabel.c_str());
    ImGui::Text("t %.2f / %.2f s   samples fed %zu   loop %llu", state.traceTime, state.traceDuration,
                state.samplesFed, static_cast<unsigned long long>(state.loops));
    if (ImGui::SmallButton(state.paused ? "resume (Space)" : "pause (Space)")) requests.togglePause = true;
    chooseByName("predictor", state.predictors, choices.predictor);
    if (!state.predictorState.empty()) {
        ImGui::TextWrapped("%s", state.predictorState.c_str());
        helpTooltip("the adaptive filter's measurement noise, estimated from the samples, and its process noise "
                    "relative to the default: below 1 on slow motion, above on fast turns");
    }
    chooseByName("deflection", state.deflections, choices.deflection);
    const char* filters[] = {"nearest", "bilinear"};
    ImGui::SetNextItemWidth(160.0f);
    ImGui::Combo("warp sampling", &choices.filter, filters, 2);
    ImGui::SetNextItemWidth(160.0f);
    ImGui::SliderFloat("extra latency ms", &choices.extraLatencyMs, 0.0f, 100.0f, "%.0f");
    ImGui::Checkbox("side-by-side stereo", &choices.stereo);
    if (choices.stereo) {
        ImGui::SameLine();
        ImGui::SetNextItemWidth(120.0f);
        ImGui::SliderFloat("IPD mm", &choices.ipdMm, 50.0f, 80.0f, "%.1f");
    }
    ImGui::Text("eye %dx%d   step-1 horizon %.1f ms", state.eyeSize.x, state.eyeSize.y, state.horizon1 * 1e3);
    helpTooltip("from the latest sample fed to the predicted display time");
    ImGui::Text("start->display %.1f ms   re-read->display %.1f ms", state.startToDisplay * 1e3,
                state.rereadToDisplay * 1e3);
    ImGui::Text("step 1 -> 2: %.3f deg   uncovered %llu px", state.deflectionDeg,
                static_cast<unsigned long long>(state.uncoveredPixels));
    helpTooltip("rotation between the two predictions, which the deflection corrects; output pixels the "
                "deflected image does not cover (border)");
    if (state.shift) ImGui::Text("shift %.1f, %.1f px (GL, y up)", state.shift->x, state.shift->y);
    ImGui::TextColored(kSelectedColour, "predicted vs true: %.3f deg   %.1f mm", state.errorDeg, state.errorMm);
    const std::size_t predictor = std::size_t(choices.predictor), deflection = std::size_t(choices.deflection);
    const FrameHistory& selected = historyOf(predictor, deflection);
    const FrameHistory& undeflected = historyOf(predictor, 0);
    char overlay[128];
    std::snprintf(overlay, sizeof overlay, "deg, last %d frames: mean %.3f max %.3f (no deflection %.3f)",
                  selected.count(), selected.mean(), selected.max(), undeflected.mean());
    ImGui::PlotLines("##error", selected.data(), selected.count(), selected.offset(), overlay, 0.0f,
                     std::max(undeflected.max() * 1.1f, 0.01f), ImVec2(ImGui::GetContentRegionAvail().x, 80.0f));
    // Every predictor x deflection on the same motion: mean (max) degrees over the window.
    if (ImGui::BeginTable("errors", 4, ImGuiTableFlags_BordersInnerH | ImGuiTableFlags_SizingStretchProp)) {
        ImGui::TableSetupColumn("predictor");
        for (const auto& name : state.deflections) ImGui::TableSetupColumn(name.c_str());
        ImGui::TableHeadersRow();
        for (std::size_t p = 0; p < state.predictors.size(); ++p) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(state.predictors[p].c_str());
            for (std::size_t d = 0; d < deflections; ++d) {
                ImGui::TableNextColumn();
                const FrameHistory& h = historyOf(p, d);
                if (p == predictor && d == deflection) ImGui::TextColored(kSelectedColour, "%.3f (%.2f)", h.mean(), h.max());
                else ImGui::Text("%.3f (%.2f)", h.mean(), h.max());
            }
        }
        ImGui::EndTable();
    }
    ImGui::TextDisabled("mean (max) deg over the last %d frames", FrameHistory::kFrames);
}

}  // namespace

void drawImmersivePanel(const ImmersivePanelState& state, ImmersiveChoices& choices, ImmersiveRequests& requests) {
    ImGui::SetNextWindowPos(ImVec2(8.0f, 8.0f), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(400.0f, std::max(float(state.windowSize.y) - 16.0f, 200.0f)), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(0.85f);
    ImGui::Begin("Strata - immersive");
    ImGui::TextWrapped("%s   %s", state.sceneName.c_str(), state.techniqueId.c_str());
    ImGui::TextWrapped("%s", state.renderer.c_str());
    if (ImGui::CollapsingHeader("Head tracking", ImGuiTreeNodeFlags_DefaultOpen)) drawHeadTracking(state, choices, requests);
    if (state.zoom && ImGui::CollapsingHeader("Zoom rendering", ImGuiTreeNodeFlags_DefaultOpen)) {
        ImGui::Text("head %.0f deg/s", state.headDegPerSecond);
        drawZoomSection(*state.zoom, true);
    }
    if (state.lod && ImGui::CollapsingHeader("Level of detail", ImGuiTreeNodeFlags_DefaultOpen))
        drawLodSection(*state.lod, state.zoom ? state.zoom->lodBoundPx() : 0.0);
    if (ImGui::CollapsingHeader("GPU time", ImGuiTreeNodeFlags_DefaultOpen)) {
        ImGui::Text("GPU %.3f ms   CPU %.3f ms per eye   %.0f fps", state.frame->gpuMs, state.frame->cpuMs,
                    ImGui::GetIO().Framerate);
    }
    drawErrorLines(state.lastGlError, state.lastError);
    ImGui::End();
}

}  // namespace strata
