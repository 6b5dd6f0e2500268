#pragma once
// The viewer's error view: the exact reference (`abuffer`) rendered on the same frame as the
// technique, and the per-pixel |technique - reference| in false colour with RMSE, PSNR and the
// worst pixel (render/error_map.hpp). The split view uses the same reference for each half's
// error. The reference renders at most once per frame however many images are compared.
#include "frame/frame_renderer.hpp"
#include "oit/technique.hpp"
#include "render/error_map.hpp"

#include <cstdint>
#include <memory>

namespace strata {

inline constexpr const char* kReferenceTechnique = "abuffer";

class ErrorView {
public:
    ErrorView();

    // Renders the reference for frame `frameIndex` unless it already did (same frame).
    void renderReference(const GpuScene& scene, const Camera& camera, glm::ivec2 size, std::uint64_t frameIndex);
    // `image` (RGBA32F of the frame's size) against the reference; with `falseColour` the
    // view's image is updated and the figures kept for the panel.
    ErrorMapStats compare(GLuint image, glm::ivec2 size, bool falseColour);

    GLuint falseColor() const { return map_.falseColor(); }
    const ErrorMapStats& stats() const { return stats_; }
    double referenceGpuMs() const { return reference_.gpuMs; }
    const TechniqueStats& referenceStats() const { return reference_.stats; }
    float& scale() { return scale_; }

    // The panel's part under the view selector: the figures, the colour rule, the scale.
    void drawPanel(const char* techniqueId);
    // One line for the smoke tests: "error: ... rmse=... psnr=... max=... worst=X,Y".
    void printFigures(const char* techniqueId, glm::ivec2 size) const;

private:
    FrameRenderer renderer_;
    std::unique_ptr<Technique> abuffer_;
    ErrorMap map_;
    FrameResult reference_;
    std::uint64_t renderedFrame_ = ~std::uint64_t(0);
    glm::ivec2 renderedSize_{0};
    ErrorMapStats stats_;
    float scale_ = 0.05f;
};

}  // namespace strata
