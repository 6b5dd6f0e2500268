#pragma once
// The immersive mode's ImGui panel (viewer/immersive.hpp): the trace's clock, the predictor,
// deflection and stereo choices, the two-step timing, the viewing error of the selected
// combination with its plot, and every predictor x deflection side by side. Like the viewer's
// panel it reads a snapshot, edits copies of the choices and returns requests (the zoom and
// level-of-detail sections edit their drivers, as in the walkthrough panel); it knows the
// predictors and deflections by name only, so it needs no tracking library.
#include "frame_history.hpp"

#include "frame/frame_renderer.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace strata {

class ZoomDriver;
namespace lod {
class LodController;
}

// What the panel lets the user change; the mode uses them from the next frame on.
struct ImmersiveChoices {
    int predictor = 0;            // index into ImmersivePanelState::predictors
    int deflection = 0;           // index into ImmersivePanelState::deflections
    int filter = 1;               // DeflectFilter: 0 nearest, 1 bilinear
    float extraLatencyMs = 0.0f;
    bool stereo = false;
    float ipdMm = 64.0f;
};

struct ImmersiveRequests {
    bool togglePause = false;
};

struct ImmersivePanelState {
    glm::ivec2 windowSize{0}, eyeSize{0};
    ZoomDriver* zoom = nullptr;   // zoom rendering: its section edits the driver's choices
    lod::LodController* lod = nullptr;  // level of detail: its section as in the walkthrough panel
    double headDegPerSecond = 0.0;
    std::string sceneName, techniqueId, renderer;
    // Trace and its clock.
    std::string traceName, truthLabel;
    double traceTime = 0.0, traceDuration = 0.0;   // seconds since the trace's first sample
    std::size_t samplesFed = 0;
    std::uint64_t loops = 0;
    bool paused = false;
    // What can be chosen, by name.
    std::vector<std::string> predictors, deflections;
    std::string predictorState;  // the selected predictor's adapted noise, empty if it has none
    // Two-step timing and the last deflection.
    double horizon1 = 0.0, startToDisplay = 0.0, rereadToDisplay = 0.0;  // seconds
    double deflectionDeg = 0.0;
    std::uint64_t uncoveredPixels = 0;
    std::optional<glm::vec2> shift;   // the last shift (GL pixels, y up) when the deflection shifts
    // Viewing error: the selected combination's last, and each combination's recent history in
    // degrees, predictor-major (index predictor * deflections.size() + deflection).
    double errorDeg = 0.0, errorMm = 0.0;
    const std::vector<FrameHistory>* errorHistory = nullptr;
    const FrameResult* frame = nullptr;
    std::string lastGlError, lastError;
};

void drawImmersivePanel(const ImmersivePanelState& state, ImmersiveChoices& choices, ImmersiveRequests& requests);

}  // namespace strata
