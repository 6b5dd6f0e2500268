#include "lod_panel.hpp"

#include "lod_options.hpp"

#include <imgui.h>

#include <cmath>
#include <cstdio>

namespace strata {
namespace {

constexpr const char* kModeNames[] = {"geometry", "impostors", "auto"};
constexpr int kListedObjects = 200;  // the table lists this many units; the totals count all

}  // namespace

void drawLodSection(lod::LodController& lod, double budgetBoundPx) {
    int mode = int(lod.options().mode);
    if (ImGui::Combo("level of detail", &mode, kModeNames, 3)) lod.setMode(lod::LodMode(mode));
    float maxError = float(lod.options().maxErrorPx);
    if (lod.options().mode == lod::LodMode::Auto && budgetBoundPx > 0.0)
        ImGui::Text("max error %.2f px, set by the frame budget", budgetBoundPx);
    else if (lod.options().mode == lod::LodMode::Auto &&
             ImGui::SliderFloat("max error px", &maxError, 0.25f, 16.0f, "%.2f", ImGuiSliderFlags_Logarithmic))
        lod.setMaxErrorPx(maxError);
    const lod::LodSelection& s = lod.selection();
    ImGui::TextWrapped("%s", lodSummary(lod).c_str());
    if (lod.options().mode != lod::LodMode::Geometry)
        ImGui::Text("predicted %.2f ms, all geometry %.2f ms", s.predictedMs, s.geometryOnlyMs);
    if (const lod::ImpostorSet* set = lod.impostors()) {
        const lod::ImpostorMemory m = set->bytes();
        ImGui::Text("%d impostors baked in %.0f ms: images %.2f MB, rectangles %.1f kB, vertices %.2f MB",
                    set->bakedImpostors(), set->bakeMs(), double(m.images) / 1e6, double(m.rectangles) / 1e3,
                    double(m.vertexBuffer) / 1e6);
        const lod::ImpostorSettings& is = set->settings();
        ImGui::Text("%d views, %d px, %d slices, overlap %.2f", is.views, is.resolution, is.slices, is.overlap);
        if (const lod::ImpostorCache* cache = lod.cache()) {
            const lod::ImpostorCacheCounts& c = cache->counts();
            ImGui::Text("cache %s: %d loaded (%.0f ms), %d stored, %d evicted, %d unreadable", cache->folder().c_str(),
                        c.hits, c.loadMs, c.stores, c.evicted, c.unreadable);
        }
    }
    // One row per LOD unit (a model instance's parts of one material, or a lone object).
    const lod::LodSelection& u = lod.unitSelection();
    const lod::LodUnits& units = lod.units();
    if (u.objects.empty() || !ImGui::TreeNode("units")) return;
    if (ImGui::BeginTable("lod units", 7, ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY, ImVec2(0, 200))) {
        for (const char* h : {"unit (parts)", "drawn as", "view err deg", "err px", "geom ms", "imp ms", "impostor MB"})
            ImGui::TableSetupColumn(h);
        ImGui::TableHeadersRow();
        for (int i = 0; i < int(u.objects.size()) && i < units.count() && i < kListedObjects; ++i) {
            const lod::LodDecision& d = u.objects[std::size_t(i)];
            const int representative = units.units[std::size_t(i)].objects[0];
            const lod::ImpostorSet* set = lod.impostors();
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::Text("%d (%zu)", i, units.units[std::size_t(i)].objects.size());
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(d.impostor ? "impostor" : "geometry");
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", lod.explainUnit(i).c_str());
            ImGui::TableNextColumn();
            if (set && set->impostorOf(representative))
                ImGui::Text("%.1f", double(set->nearestViewAngle(representative, lod.lastEye())) * 180.0 / M_PI);
            ImGui::TableNextColumn();
            ImGui::Text("%.2f", d.errorPx);
            ImGui::TableNextColumn();
            ImGui::Text("%.3f", d.geometryMs);
            ImGui::TableNextColumn();
            ImGui::Text("%.3f", d.impostorMs);
            ImGui::TableNextColumn();
            // The unit's impostor, shared by every unit of the same parts.
            if (set && set->impostorOf(representative))
                ImGui::Text("%.2f", double(set->impostorOf(representative)->bytes().total()) / 1e6);
        }
        ImGui::EndTable();
    }
    ImGui::TreePop();
}

void printLodFigures(const lod::LodController& lod) {
    std::printf("%s\n", lodSummary(lod).c_str());
}

}  // namespace strata
