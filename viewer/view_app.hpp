#pragma once
// `strata view`: the interactive window (GLFW + Dear ImGui) over the same frame pipeline the
// headless commands use.
#include "view_kind.hpp"
#include "lod_options.hpp"
#include "zoom_options.hpp"

#include "gl/context.hpp"
#include "oit/technique_settings.hpp"

#include <glm/glm.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace strata {

struct ViewOptions {
    std::string scene = "builtin:default";
    std::string mode = "abuffer";
    ViewKind view = ViewKind::Image;                     // --view: what the window shows first
    std::string splitWith = "f2b";                       // --split-with: B of the split view
    float splitAt = 0.5f;                                // --split-at: the divider, 0..1 of the width
    std::optional<glm::ivec2> inspect;                   // --inspect X,Y: window pixel, from the top-left
    // --settings and --set (or --mode auto's pick), resolved against every technique once the
    // window's context shows the device: its defaults first (oit/device_defaults.hpp) unless
    // deviceDefaults is off.
    std::vector<SettingAssignment> settingAssignments;
    bool deviceDefaults = true;
    std::optional<std::filesystem::path> playPath;       // --path: play a camera path
    std::optional<std::filesystem::path> recordPath;     // --record: record the camera to a path file
    bool immersive = false;
    std::optional<std::filesystem::path> trace;          // --trace (immersive)
    // Immersive mode's starting choices (viewer/immersive.hpp); the panel changes them live.
    std::string predictor = "kalman";
    std::string deflect = "homography";
    bool stereo = false;
    double ipdMm = 64.0;
    double extraLatencyMs = 0.0;                         // added to the measured frame time
    // Smoke testing: exit after this many frames (0 = run until closed), saving a screenshot.
    int exitAfterFrames = 0;
    std::optional<std::filesystem::path> screenshot;
    int width = 1280, height = 800;
    // Zoom rendering (--zoom, or --frame-budget-ms with --zoom-controller; the panel changes them).
    ZoomArgs zoom;
    // Per-object level of detail (--lod and the impostor settings; the panel changes the mode).
    LodArgs lod;
};

// The panel's zoom choices the command line asks for.
struct ZoomChoices;
ZoomChoices zoomChoicesFrom(const ViewOptions& options);

// Every technique's settings for the window on `device` (ViewOptions::settingAssignments).
SettingsById viewSettings(const ViewOptions& options, const gl::DeviceInfo& device);

// Runs the window loop (viewer/window_loop.hpp) in the walkthrough mode, or with `immersive` in
// the head-tracked mode (viewer/immersive.hpp), until the window closes or the smoke test is
// done. Bad input throws before a window opens; so does a missing window (std::runtime_error).
int runViewer(const ViewOptions& options);

// True when a display is reachable (DISPLAY or WAYLAND_DISPLAY set and GLFW initialises).
bool displayAvailable();

}  // namespace strata
