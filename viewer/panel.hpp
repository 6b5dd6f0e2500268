#pragma once
// The viewer's ImGui panel: technique choice and settings, live GPU time per pass with a
// plot of recent frames, fragment counts and memory, GL errors, scene and camera state, and the
// walkthrough keys. It reads a snapshot of the viewer's state and returns what the user asked
// for; the viewer applies the requests between frames (never while the panel is drawing).
#include "frame_history.hpp"
#include "view_kind.hpp"

#include "gl/context.hpp"
#include "oit/technique.hpp"
#include "frame/frame_renderer.hpp"
#include "render/gpu_scene.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

namespace strata {
namespace lod {
class LodController;
}

class ZoomDriver;

// The last frame on which every transparent fragment was counted.
struct FragmentCount {
    std::uint64_t frame = 0;
    std::uint64_t total = 0;
    TechniqueStats stats;
};

struct PanelState {
    const GpuScene* scene = nullptr;
    const gl::DeviceInfo* device = nullptr;
    Technique* technique = nullptr;            // null only when creation failed
    std::string techniqueId;
    const FrameResult* frame = nullptr;
    const FrameHistory* history = nullptr;     // GPU ms
    std::optional<FragmentCount> count;
    std::uint64_t frameIndex = 0;
    glm::ivec2 size{0};
    // Camera and walkthrough.
    const char* navigation = "orbit";
    glm::vec3 cameraPosition{0.0f};
    float nearPlane = 0.0f, farPlane = 0.0f;
    bool recording = false;
    std::size_t recordedSamples = 0;
    std::string recordPath;
    bool hasPath = false, playing = false;
    double pathTime = 0.0, pathDuration = 0.0;
    // Messages.
    std::string lastError;      // render or shader error, empty when none
    std::string lastGlError;
    std::string lastSaved;      // last screenshot or path written
    ZoomDriver* zoom = nullptr; // zoom rendering: its section edits the driver's choices
    lod::LodController* lod = nullptr;  // level of detail: its section switches the mode
    // Drawn under the view selector: the error and split views' figures (viewer/error_view.hpp,
    // viewer/split_view.hpp), owned by the mode that shows them.
    std::function<void()> viewDetails;
};

// Settings the panel edits in place: copies, which the viewer applies between frames.
struct PanelSettings {
    ViewKind view = ViewKind::Image;
    SettingValues technique;    // the current technique's settings
    bool countEveryFrame = false;
    int countInterval = 30;     // count fragments every N frames (0 = never) unless every frame
    bool vsync = true;
};

struct PanelRequests {
    std::optional<std::string> technique;   // switch to this id
    bool reload = false;
    bool screenshot = false;
    bool toggleRecording = false;
    bool togglePlayback = false;
    bool toggleNavigation = false;
    bool vsyncChanged = false;
};

// Draws the panel window; returns its rectangle in window pixels (x, y, width, height) with the
// origin at the top-left, as ImGui places it.
glm::vec4 drawPanel(const PanelState& state, PanelSettings& settings, PanelRequests& requests);

}  // namespace strata
