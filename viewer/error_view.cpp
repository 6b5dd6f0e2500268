#include "error_view.hpp"

#include "panel_widgets.hpp"

#include <imgui.h>

#include <cstdio>

namespace strata {

ErrorView::ErrorView() : abuffer_(createTechnique(kReferenceTechnique)) {}

void ErrorView::renderReference(const GpuScene& scene, const Camera& camera, glm::ivec2 size, std::uint64_t frameIndex) {
    if (frameIndex == renderedFrame_ && size == renderedSize_) return;
    FrameOptions options;
    options.timePasses = true;
    reference_ = renderer_.render(scene, camera, size, abuffer_.get(), options);
    renderedFrame_ = frameIndex;
    renderedSize_ = size;
}

ErrorMapStats ErrorView::compare(GLuint image, glm::ivec2 size, bool falseColour) {
    ErrorMapStats s = map_.compare(image, renderer_.targets().outputColor(), size, scale_, falseColour);
    if (falseColour) stats_ = s;
    return s;
}

void ErrorView::drawPanel(const char* techniqueId) {
    ImGui::TextWrapped("per pixel, max over RGB of |%s - %s| (linear), %s rendered on the same frame", techniqueId,
                       kReferenceTechnique, kReferenceTechnique);
    ImGui::Text("RMSE %.3e   PSNR %.2f dB", stats_.rmse, stats_.psnr);
    if (stats_.maxAbsError > 0.0)
        ImGui::Text("worst pixel %d, %d (from the top: %d)   error %.4f", stats_.worstPixel.x, stats_.worstPixel.y,
                    renderedSize_.y - 1 - stats_.worstPixel.y, stats_.maxAbsError);
    else
        ImGui::TextUnformatted("no pixel differs");
    ImGui::Text("reference %.3f ms GPU (not in the technique's time)", reference_.gpuMs);
    ImGui::SetNextItemWidth(160.0f);
    ImGui::SliderFloat("full red at", &scale_, 1e-4f, 1.0f, "%.4f", ImGuiSliderFlags_Logarithmic);
    helpTooltip("grey: exactly equal (the reference's luminance, dimmed); dark blue through cyan, green and "
                "yellow to red: error from just above 0 up to this value and beyond");
}

void ErrorView::printFigures(const char* techniqueId, glm::ivec2 size) const {
    std::printf("error: %s against %s %dx%d rmse=%.6e psnr=%.4f max=%.6e worst=%d,%d\n", techniqueId,
                kReferenceTechnique, size.x, size.y, stats_.rmse, stats_.psnr, stats_.maxAbsError, stats_.worstPixel.x,
                stats_.worstPixel.y);
}

}  // namespace strata
