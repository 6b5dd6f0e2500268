#include "panel.hpp"
#include "lod_panel.hpp"
#include "zoom_driver.hpp"

#include "panel_widgets.hpp"
#include "settings_panel.hpp"
#include "view_panel.hpp"

#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <string>

namespace strata {

namespace {

std::string formatBytes(std::uint64_t bytes) {
    char text[64];
    if (bytes >= (1ull << 30)) std::snprintf(text, sizeof text, "%.2f GiB", double(bytes) / double(1ull << 30));
    else if (bytes >= (1ull << 20)) std::snprintf(text, sizeof text, "%.2f MiB", double(bytes) / double(1ull << 20));
    else if (bytes >= (1ull << 10)) std::snprintf(text, sizeof text, "%.1f KiB", double(bytes) / double(1ull << 10));
    else std::snprintf(text, sizeof text, "%llu B", static_cast<unsigned long long>(bytes));
    return text;
}

std::string techniqueLabel(const TechniqueInfo& info) {
    std::string label = info.id + "  [" + info.family;
    if (info.robust) label += ", robust";
    if (info.handlesCoplanarity) label += ", coplanarity";
    return label + "]";
}

void drawTechnique(const PanelState& state, PanelSettings& settings, PanelRequests& requests) {
    const TechniqueEntry* current = findTechnique(state.techniqueId);
    std::string preview = current ? techniqueLabel(current->info) : state.techniqueId;
    ImGui::SetNextItemWidth(-1.0f);
    if (ImGui::BeginCombo("##technique", preview.c_str())) {
        for (const auto& entry : techniqueRegistry()) {
            bool selected = entry.info.id == state.techniqueId;
            if (ImGui::Selectable(techniqueLabel(entry.info).c_str(), selected) && !selected)
                requests.technique = entry.info.id;
            helpTooltip(entry.info.description);
            if (selected) ImGui::SetItemDefaultFocus();
        }
        ImGui::EndCombo();
    }
    if (current) {
        const TechniqueInfo& info = current->info;
        ImGui::TextWrapped("%s", info.description.c_str());
        ImGui::TextWrapped("passes %s   memory %s", info.passes.c_str(), info.memoryModel.c_str());
        ImGui::Text("robust: %s   coplanarity-aware: %s   glass: %s", info.robust ? "yes" : "no",
                    info.handlesCoplanarity ? "yes" : "no", info.rgbTransmittance ? "rgb" : "scalar");
        helpTooltip("glass: how a transmissive material's coloured filter composites. rgb: per channel, exact; "
                    "scalar: one alpha (1 - mean transmittance), the tint lost (`strata modes`)");
    }
    if (current) drawSettings(current->settings, settings.technique);
}

void drawTiming(const PanelState& state) {
    const FrameResult& frame = *state.frame;
    ImGui::Text("%dx%d   GPU %.3f ms   CPU %.3f ms   %.0f fps", state.size.x, state.size.y, frame.gpuMs, frame.cpuMs,
                ImGui::GetIO().Framerate);
    if (ImGui::BeginTable("passes", 3, ImGuiTableFlags_BordersInnerH | ImGuiTableFlags_SizingStretchProp)) {
        ImGui::TableSetupColumn("pass");
        ImGui::TableSetupColumn("GPU ms");
        ImGui::TableSetupColumn("CPU ms");
        ImGui::TableHeadersRow();
        for (const auto& p : frame.passTimes) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(p.name.c_str());
            ImGui::TableNextColumn();
            ImGui::Text("%.3f", p.gpuMs);
            ImGui::TableNextColumn();
            ImGui::Text("%.3f", p.cpuMs);
        }
        ImGui::EndTable();
    }
    if (!frame.transparencyPass) ImGui::TextDisabled("no transparency pass (nothing transparent in view)");
    ImGui::Text("objects culled %zu of %zu (unit instances %zu of %d) outside the view frustum", frame.objectsCulled,
                state.scene->objects().size(), frame.unitsCulled, state.scene->cullHierarchy().unitCount());
    // Objects of one mesh and material go out in one instanced draw (GpuScene::drawObjects).
    ImGui::Text("GL draws %llu for %zu objects in view", static_cast<unsigned long long>(frame.drawCalls),
                state.scene->objects().size() - frame.objectsCulled);
    ImGui::Text("render thread CPU %.3f ms", frame.threadCpuMs);
    const FrameHistory& h = *state.history;
    char overlay[96];
    std::snprintf(overlay, sizeof overlay, "GPU ms, last %d: mean %.3f max %.3f", h.count(), h.mean(), h.max());
    ImGui::PlotLines("##gpu", h.data(), h.count(), h.offset(), overlay, 0.0f, std::max(h.max() * 1.15f, 0.01f),
                     ImVec2(ImGui::GetContentRegionAvail().x, 70.0f));  // 1.86 takes no -1 here
}

void drawFragments(const PanelState& state, PanelSettings& settings) {
    ImGui::Checkbox("count every frame", &settings.countEveryFrame);
    if (!settings.countEveryFrame) {
        ImGui::SameLine();
        ImGui::SetNextItemWidth(90.0f);
        ImGui::InputInt("every N frames", &settings.countInterval);
        settings.countInterval = std::clamp(settings.countInterval, 0, 100000);
    }
    const TechniqueStats& live = state.frame->stats;
    ImGui::Text("memory %s   passes %d   object draws %llu", formatBytes(live.bytes).c_str(), live.passes,
                static_cast<unsigned long long>(live.objectDraws));
    if (!state.count) {
        ImGui::TextDisabled("fragments not counted yet");
        return;
    }
    const FragmentCount& c = *state.count;
    double ratio = c.total ? double(c.stats.fragmentsCaptured) / double(c.total) : 1.0;
    ImGui::Text("counted at frame %llu (%llu frames ago)", static_cast<unsigned long long>(c.frame),
                static_cast<unsigned long long>(state.frameIndex - c.frame));
    ImGui::Text("total %llu   captured %llu   dropped %llu", static_cast<unsigned long long>(c.total),
                static_cast<unsigned long long>(c.stats.fragmentsCaptured),
                static_cast<unsigned long long>(c.stats.fragmentsDropped));
    ImVec4 ratioColour = ratio >= 1.0 ? ImVec4(0.5f, 0.9f, 0.5f, 1.0f) : ImVec4(1.0f, 0.6f, 0.3f, 1.0f);
    ImGui::TextColored(ratioColour, "robustness ratio %.4f", ratio);
    ImGui::SameLine();
    if (c.stats.overflowed) ImGui::TextColored(kErrorColour, "OVERFLOWED");
    else ImGui::TextUnformatted("no overflow");
    ImGui::Text("regrows %d   tiles %d", c.stats.regrows, c.stats.tiles);
}

// Which transparent objects the volumetric techniques (ll-volume, abuffer-volume) render as
// media, and why the others with a volume material are drawn as surfaces.
void drawVolumes(const GpuScene& scene) {
    const auto& kinds = scene.objectVolumes();
    std::size_t declared = 0, volumes = 0;
    for (std::size_t i = 0; i < kinds.size(); ++i) {
        if (!scene.scene().materials[std::size_t(scene.objects()[i].material)].volume) continue;
        ++declared;
        if (kinds[i].volume) ++volumes;
    }
    if (declared == 0) return;
    if (!ImGui::TreeNode("volumes", "volumes %zu of %zu declared", volumes, declared)) return;
    for (std::size_t i = 0; i < kinds.size(); ++i) {
        const Material& m = scene.scene().materials[std::size_t(scene.objects()[i].material)];
        if (!m.volume) continue;
        const ImVec4 colour = kinds[i].volume ? ImVec4(0.5f, 0.9f, 0.5f, 1.0f) : ImVec4(1.0f, 0.6f, 0.3f, 1.0f);
        ImGui::TextColored(colour, "#%zu %s: %s", i, m.name.c_str(), kinds[i].status.c_str());
    }
    ImGui::TreePop();
}

void drawScene(const PanelState& state) {
    const GpuScene& scene = *state.scene;
    const Bounds& b = scene.bounds();
    ImGui::Text("%s", scene.scene().name.empty() ? "(unnamed scene)" : scene.scene().name.c_str());
    ImGui::Text("objects %zu (opaque %zu, transparent %zu)", scene.objects().size(), scene.opaqueObjects().size(),
                scene.transparentObjects().size());
    ImGui::Text("triangles %zu", scene.triangleCount());
    // Instances share their mesh: memory follows the distinct meshes, not the objects.
    ImGui::Text("distinct meshes %zu: %zu triangles, %.1f MiB on the GPU", scene.meshCount(),
                scene.meshTriangleCount(), double(scene.meshBytes()) / (1024.0 * 1024.0));
    if (scene.textureBytes() > 0)
        ImGui::Text("textures %zu (%.1f MiB on the GPU)", scene.scene().images.size(),
                    double(scene.textureBytes()) / (1024.0 * 1024.0));
    // Which lights shade it: the file's KHR_lights_punctual ones, or Strata's default rig.
    if (scene.scene().lights.empty())
        ImGui::TextUnformatted("lights: default rig (one directional light)");
    else
        ImGui::Text("lights: %zu KHR_lights_punctual", scene.scene().lights.size());
    // Coloured glass, and whether the technique shown composites it per channel.
    if (scene.hasColoredFilters()) {
        const bool rgb = state.technique && state.technique->info().rgbTransmittance;
        ImGui::TextColored(rgb ? ImVec4(0.5f, 0.9f, 0.5f, 1.0f) : ImVec4(1.0f, 0.6f, 0.3f, 1.0f), "glass: %s",
                           rgb ? "coloured filters per channel" : "coloured filters as grey (scalar form)");
        helpTooltip("transmissive materials filter what is behind them per channel; `strata modes` lists which "
                    "techniques composite that (filters: rgb) and which take one alpha, losing the tint");
    }
    if (!b.empty()) {
        glm::vec3 e = b.max - b.min;
        ImGui::Text("bounds %.3g x %.3g x %.3g", e.x, e.y, e.z);
    }
    drawVolumes(scene);
    if (state.device) ImGui::TextWrapped("%s", state.device->renderer.c_str());
}

void drawCamera(const PanelState& state, PanelRequests& requests) {
    ImGui::Text("navigation: %s", state.navigation);
    ImGui::SameLine();
    if (ImGui::SmallButton("switch (Tab)")) requests.toggleNavigation = true;
    ImGui::Text("eye %.3g %.3g %.3g   near %.3g far %.3g", state.cameraPosition.x, state.cameraPosition.y,
                state.cameraPosition.z, state.nearPlane, state.farPlane);
    if (state.hasPath) {
        ImGui::Text("path %s  %.2f / %.2f s", state.playing ? "playing" : "paused", state.pathTime,
                    state.pathDuration);
        ImGui::SameLine();
        if (ImGui::SmallButton(state.playing ? "pause (Space)" : "play (Space)")) requests.togglePlayback = true;
    }
    if (state.recording) {
        ImGui::TextColored(ImVec4(1.0f, 0.35f, 0.3f, 1.0f), "REC %zu samples -> %s", state.recordedSamples,
                           state.recordPath.c_str());
        ImGui::SameLine();
        if (ImGui::SmallButton("stop (R)")) requests.toggleRecording = true;
    } else if (ImGui::SmallButton("record path (R)")) {
        requests.toggleRecording = true;
    }
    ImGui::SameLine();
    if (ImGui::SmallButton("screenshot (P)")) requests.screenshot = true;
    ImGui::SameLine();
    if (ImGui::SmallButton("reload (F5)")) requests.reload = true;
    if (ImGui::TreeNode("keys")) {
        ImGui::TextUnformatted("orbit: left-drag turn, wheel zoom\n"
                               "walk: WASD move, Q/E down/up, right-drag look,\n"
                               "      shift faster, wheel walking speed\n"
                               "Tab orbit/walk   F12/P screenshot   R record\n"
                               "Space play/pause path   F5 reload shaders");
        ImGui::TreePop();
    }
}

}  // namespace

glm::vec4 drawPanel(const PanelState& state, PanelSettings& settings, PanelRequests& requests) {
    ImGui::SetNextWindowPos(ImVec2(8.0f, 8.0f), ImGuiCond_FirstUseEver);
    float height = std::max(ImGui::GetIO().DisplaySize.y - 16.0f, 200.0f);
    ImGui::SetNextWindowSize(ImVec2(380.0f, height), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(0.85f);
    ImGui::Begin("Strata");
    if (ImGui::CollapsingHeader("View", ImGuiTreeNodeFlags_DefaultOpen)) {
        const FrameResult* f = state.frame;
        drawViewSection(settings.view, f && f->coplanarity ? &*f->coplanarity : nullptr, f ? f->coplanarityMs : 0.0);
        if (state.viewDetails) state.viewDetails();
    }
    if (ImGui::CollapsingHeader("Technique", ImGuiTreeNodeFlags_DefaultOpen)) drawTechnique(state, settings, requests);
    if (ImGui::CollapsingHeader("GPU time", ImGuiTreeNodeFlags_DefaultOpen)) drawTiming(state);
    if (ImGui::CollapsingHeader("Fragments and memory", ImGuiTreeNodeFlags_DefaultOpen)) drawFragments(state, settings);
    if (ImGui::CollapsingHeader("Scene", ImGuiTreeNodeFlags_DefaultOpen)) drawScene(state);
    if (ImGui::CollapsingHeader("Camera", ImGuiTreeNodeFlags_DefaultOpen)) drawCamera(state, requests);
    if (state.zoom && ImGui::CollapsingHeader("Zoom rendering", ImGuiTreeNodeFlags_DefaultOpen))
        drawZoomSection(*state.zoom, false);
    if (state.lod && ImGui::CollapsingHeader("Level of detail", ImGuiTreeNodeFlags_DefaultOpen))
        drawLodSection(*state.lod, state.zoom ? state.zoom->lodBoundPx() : 0.0);
    if (ImGui::Checkbox("vsync", &settings.vsync)) requests.vsyncChanged = true;
    ImGui::SameLine();
    drawErrorLines(state.lastGlError, state.lastError);
    if (!state.lastSaved.empty()) ImGui::TextWrapped("%s", state.lastSaved.c_str());
    ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
    ImGui::End();
    return {pos.x, pos.y, size.x, size.y};
}

}  // namespace strata
