#include "view_panel.hpp"

#include "panel_widgets.hpp"

#include "image/image.hpp"

#include <imgui.h>

#include <cstdint>

namespace strata {
namespace {

void drawLegend(const CoplanarityStats& stats) {
    const double pixels = double(std::max<std::uint64_t>(stats.pixels(), 1));
    if (!ImGui::BeginTable("legend", 3, ImGuiTableFlags_SizingFixedFit)) return;
    // Bins 0 and 1 share grey ("none"); the last bin is "9 or more".
    for (int k = 1; k < kCoplanarityBins; ++k) {
        std::uint64_t count = stats.pixelsByLargestLayer[std::size_t(k)];
        if (k == 1) count += stats.pixelsByLargestLayer[0];
        const glm::vec3 c = coplanarityColor(k);
        // ImGui draws without sRGB conversion: give it the encoded colour the window shows.
        const ImVec4 swatch(linearToSrgb(c.r), linearToSrgb(c.g), linearToSrgb(c.b), 1.0f);
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::ColorButton(coplanarityColorName(k), swatch, ImGuiColorEditFlags_NoTooltip, ImVec2(14.0f, 14.0f));
        ImGui::TableNextColumn();
        if (k == 1) ImGui::TextUnformatted("none (0 or 1 per layer)");
        else if (k == kCoplanarityBins - 1) ImGui::Text("%d or more in a layer", k);
        else ImGui::Text("%d in a layer", k);
        ImGui::TableNextColumn();
        ImGui::Text("%6.2f %%", 100.0 * double(count) / pixels);
    }
    ImGui::EndTable();
}

}  // namespace

void drawViewSection(ViewKind& view, const CoplanarityStats* stats, double detectorMs) {
    for (ViewKind v : kViewKinds) {
        if (ImGui::RadioButton(viewLabel(v), view == v)) view = v;
        ImGui::SameLine();
    }
    ImGui::NewLine();
    if (view != ViewKind::CoplanarityHeatmap) return;
    ImGui::TextWrapped("per pixel, the largest number of transparent fragments in one depth layer "
                       "(the reference's tie rule), in Fig. 13's colours; computed on the GPU each frame");
    if (!stats) {
        ImGui::TextDisabled("no heatmap yet");
        return;
    }
    ImGui::Text("C_p %.4f   (%llu of %llu pixels with fragments)", stats->coplanarityProbability(),
                static_cast<unsigned long long>(stats->pixelsWithTies()),
                static_cast<unsigned long long>(stats->pixelsWithFragments()));
    ImGui::Text("R_h one per layer (f2b) %.4f", stats->oneFragmentPerLayerRobustness());
    helpTooltip("layers / fragments: what peeling that keeps one fragment per depth layer captures "
                "(f2b, dual, bun without the paper's extensions)");
    ImGui::Text("detector %.3f ms GPU", detectorMs);
    drawLegend(*stats);
}

}  // namespace strata
