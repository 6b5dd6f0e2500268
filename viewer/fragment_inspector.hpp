#pragma once
// The fragment inspector: click a pixel (or `strata view --inspect X,Y`) and a window lists the
// transparent fragments there as the exact reference sorted them (the CPU ray cast of
// core/reference through the pixel centre: depth, object, primitive, colour, alpha, in the tie
// rule's compositing order) and which of them the current technique kept.
//
// No technique reports per-pixel which fragments it stored, so "kept" is inferred, and the
// window says so: the technique's pixel is compared with the reference composites of every
// prefix (the nearest k fragments over the opaque colour, k = 0..n). A prefix within 2/255 of
// the technique's colour means "consistent with keeping the nearest k"; several matching
// prefixes leave the fragments between them undecided; none means the technique kept no
// depth-ordered prefix (an approximate blend, the first-arrived rather than the nearest, or a
// pixel whose coverage the rasterizer and the ray cast decide differently at an edge).
#include "oit/technique.hpp"
#include "reference/raycast.hpp"
#include "render/gpu_scene.hpp"

#include <glm/glm.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace strata {

enum class Kept { Yes, No, Undecided };

struct Inspection {
    glm::ivec2 pixel{0};          // row 0 at the bottom (GL)
    glm::ivec2 fromTop{0};        // the same pixel, row 0 at the top (window, --inspect)
    std::string techniqueId;
    PixelSample reference;        // the ray cast's fragments, in compositing order
    std::vector<glm::vec3> prefixColours;  // [k]: the nearest k fragments over the opaque colour
    glm::vec3 techniqueColour{0.0f};
    int firstMatch = -1, lastMatch = -1;   // the range of matching prefixes; -1: none matches
    double bestDistance = 0.0;             // max-channel distance to the closest prefix
    int bestPrefix = 0;
    std::vector<Kept> kept;                // per fragment
    TechniqueStats frameStats;             // the technique's whole-frame counts, for context
};

// Pure part, testable without GL: fills prefixColours, the match range and `kept` from
// `reference` and `techniqueColour`.
void inferKept(Inspection& inspection, double tolerance = 2.0 / 255.0);

class FragmentInspector {
public:
    // Selects a pixel in window coordinates (row 0 at the top, window pixels, as a click reports)
    // and opens the window.
    void select(glm::ivec2 windowPixel) { selected_ = windowPixel; open_ = true; }
    bool active() const { return selected_.has_value() && open_; }

    // Re-inspects the selected pixel on this frame: `output` is the technique's RGBA32F image of
    // `size` (the framebuffer), `windowSize` the window in the cursor's units (HiDPI scale).
    void inspect(const GpuScene& scene, const Camera& camera, glm::ivec2 size, glm::vec2 windowSize, GLuint output,
                 const std::string& techniqueId, const TechniqueStats& stats);

    // The inspector's own ImGui window (while a pixel is selected).
    void drawWindow(const GpuScene& scene);
    // Lines for the smoke tests: "inspect: ..." then one "fragment: ..." per fragment.
    void printFigures(const GpuScene& scene) const;

private:
    std::optional<glm::ivec2> selected_;
    bool open_ = false;
    const GpuScene* scene_ = nullptr;  // the scene raycast_ was built for
    std::unique_ptr<RaycastReference> raycast_;
    std::optional<Inspection> last_;
};

// Click detection: a left press and release within a few pixels, outside the panel, is a click
// (a drag orbits the camera instead). Feed it every frame; returns the click position once.
class ClickDetector {
public:
    std::optional<glm::vec2> update(glm::vec2 cursor, bool leftDown, bool panelWantsMouse);

private:
    bool down_ = false, valid_ = false;
    glm::vec2 pressedAt_{0.0f};
};

}  // namespace strata
