#include "split_view.hpp"

#include "panel_widgets.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace strata {
namespace {

constexpr int kLineWidth = 2;         // the divider line, pixels
constexpr float kGrabDistance = 6.0f;  // how near the divider a press starts a drag, pixels

void drawHalf(const char* side, const SplitHalf& h) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::Text("%s %s", side, h.techniqueId.c_str());
    ImGui::TableNextColumn();
    ImGui::Text("%.3f", h.gpuMs);
    ImGui::TableNextColumn();
    ImGui::Text("%.2e", h.error.rmse);
    ImGui::TableNextColumn();
    ImGui::Text("%.2f", h.error.psnr);
    ImGui::TableNextColumn();
    ImGui::Text("%.2e", h.error.maxAbsError);
    ImGui::TableNextColumn();
    if (h.stats.overflowed) ImGui::TextColored(kErrorColour, "overflow");
    else ImGui::Text("%d", h.stats.passes);
}

}  // namespace

SplitView::SplitView(const std::string& techniqueB, float divider, const SettingsById& settings)
    : techniqueId_(techniqueB), technique_(createConfiguredTechnique(techniqueB, settings)),
      divider_(std::clamp(divider, 0.0f, 1.0f)) {}

void SplitView::setTechnique(const std::string& id, const SettingsById& settings) {
    auto next = createConfiguredTechnique(id, settings);
    technique_ = std::move(next);
    techniqueId_ = id;
}

int SplitView::dividerColumn(int width) const { return std::clamp(int(std::lround(divider_ * float(width))), 0, width); }

void SplitView::render(const GpuScene& scene, const Camera& camera, glm::ivec2 size, std::uint64_t frameIndex,
                       const std::string& idA, GLuint outputA, const FrameResult& frameA, ErrorView& errors,
                       const StandIns* standIns) {
    FrameOptions options;
    options.timePasses = true;
    options.standIns = standIns;  // B draws what A drew: the same objects as impostors
    const FrameResult frameB = renderer_.render(scene, camera, size, technique_.get(), options);
    errors.renderReference(scene, camera, size, frameIndex);
    a_ = {idA, frameA.gpuMs, frameA.stats, errors.compare(outputA, size, false)};
    b_ = {techniqueId_, frameB.gpuMs, frameB.stats, errors.compare(renderer_.targets().outputColor(), size, false)};

    if (!composite_.id() || size_ != size) {
        composite_ = gl::createTexture2D(GL_RGBA32F, size.x, size.y);
        size_ = size;
    }
    const int column = dividerColumn(size.x);
    if (column > 0)
        glCopyImageSubData(outputA, GL_TEXTURE_2D, 0, 0, 0, 0, composite_.id(), GL_TEXTURE_2D, 0, 0, 0, 0, column, size.y, 1);
    if (column < size.x)
        glCopyImageSubData(renderer_.targets().outputColor(), GL_TEXTURE_2D, 0, column, 0, 0, composite_.id(),
                           GL_TEXTURE_2D, 0, column, 0, 0, size.x - column, size.y, 1);
    // The line straddles the divider, clipped to the image.
    const int x0 = std::clamp(column - kLineWidth / 2, 0, std::max(size.x - kLineWidth, 0));
    const float white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    glClearTexSubImage(composite_.id(), 0, x0, 0, 0, std::min(kLineWidth, size.x), size.y, 1, GL_RGBA, GL_FLOAT, white);
}

bool SplitView::handleMouse(glm::vec2 cursor, bool leftDown, bool panelWantsMouse, glm::vec2 windowSize) {
    if (!leftDown) {
        dragging_ = false;
        return false;
    }
    if (!dragging_) {
        const float x = divider_ * windowSize.x;
        if (panelWantsMouse || std::abs(cursor.x - x) > kGrabDistance) return false;
        dragging_ = true;
    }
    if (windowSize.x > 0.0f) divider_ = std::clamp(cursor.x / windowSize.x, 0.0f, 1.0f);
    return true;
}

void SplitView::drawPanel(std::optional<std::string>& request) {
    ImGui::TextWrapped("left: the current technique; right: B, on the same frame. Drag the white line or:");
    ImGui::SetNextItemWidth(160.0f);
    ImGui::SliderFloat("divider", &divider_, 0.0f, 1.0f, "%.2f");
    ImGui::SetNextItemWidth(-1.0f);
    if (ImGui::BeginCombo("##split-with", ("B: " + techniqueId_).c_str())) {
        for (const auto& entry : techniqueRegistry()) {
            const bool selected = entry.info.id == techniqueId_;
            if (ImGui::Selectable(entry.info.id.c_str(), selected) && !selected) request = entry.info.id;
            if (selected) ImGui::SetItemDefaultFocus();
        }
        ImGui::EndCombo();
    }
    if (ImGui::BeginTable("halves", 6, ImGuiTableFlags_BordersInnerH | ImGuiTableFlags_SizingFixedFit)) {
        for (const char* h : {"half", "GPU ms", "RMSE", "PSNR", "max err", "passes"}) ImGui::TableSetupColumn(h);
        ImGui::TableHeadersRow();
        drawHalf("A", a_);
        drawHalf("B", b_);
        ImGui::EndTable();
    }
    ImGui::TextDisabled("errors over the whole frame against %s", kReferenceTechnique);
}

void SplitView::printFigures(glm::ivec2 size) const {
    auto half = [](const char* side, const SplitHalf& h) {
        std::printf(" %s=%s gpu_ms=%.3f rmse=%.6e psnr=%.4f max=%.6e", side, h.techniqueId.c_str(), h.gpuMs, h.error.rmse,
                    h.error.psnr, h.error.maxAbsError);
    };
    std::printf("split: %dx%d divider=%d", size.x, size.y, dividerColumn(size.x));
    half("A", a_);
    std::printf(" |");
    half("B", b_);
    std::printf("\n");
}

}  // namespace strata
