#pragma once
// The split A | B view: the current technique (A) left of a divider, a second technique (B)
// right of it, both rendered on the same frame (scene, camera, size), each with its GPU time and
// its error against the reference (viewer/error_view.hpp) over the whole frame. The divider is
// dragged with the mouse on the window or set with the panel's slider (`--split-at`).
#include "error_view.hpp"

#include "frame/frame_renderer.hpp"
#include "gl/objects.hpp"
#include "oit/technique.hpp"
#include "oit/technique_settings.hpp"

#include <memory>
#include <optional>
#include <string>

namespace strata {

struct SplitHalf {
    std::string techniqueId;
    double gpuMs = 0.0;
    TechniqueStats stats;
    ErrorMapStats error;
};

class SplitView {
public:
    // Throws std::invalid_argument for an unknown technique (the command line checks first).
    SplitView(const std::string& techniqueB, float divider, const SettingsById& settings);

    // Switches B (keeps the old one when creation fails, and rethrows).
    void setTechnique(const std::string& id, const SettingsById& settings);
    const std::string& techniqueId() const { return techniqueId_; }

    // Renders B on A's frame, measures both halves against the reference and composes the
    // shown image: A's texels left of the divider, B's right of it, a 2-pixel white line between.
    void render(const GpuScene& scene, const Camera& camera, glm::ivec2 size, std::uint64_t frameIndex,
                const std::string& idA, GLuint outputA, const FrameResult& frameA, ErrorView& errors,
                const StandIns* standIns = nullptr);
    GLuint composite() const { return composite_.id(); }

    // Mouse on the window (pixels from the top-left, as GLFW reports): a left press within a few
    // pixels of the divider starts a drag that moves it until release. Returns true while the
    // divider owns the mouse (the camera must then ignore the drag).
    bool handleMouse(glm::vec2 cursor, bool leftDown, bool panelWantsMouse, glm::vec2 windowSize);

    float& divider() { return divider_; }  // 0..1 of the width
    int dividerColumn(int width) const;

    // The panel's part: B's choice (sets `request`), the slider, and each half's cost and error.
    void drawPanel(std::optional<std::string>& request);
    // One line for the smoke tests: "split: A=... gpu_ms=... rmse=... | B=... divider=X".
    void printFigures(glm::ivec2 size) const;

private:
    std::string techniqueId_;
    std::unique_ptr<Technique> technique_;
    FrameRenderer renderer_;
    gl::Texture composite_;
    glm::ivec2 size_{0};
    float divider_ = 0.5f;
    bool dragging_ = false;
    SplitHalf a_, b_;
};

}  // namespace strata
