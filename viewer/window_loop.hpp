#pragma once
// The one window loop of `strata view`. It owns what every mode shares: the window and ImGui
// (set up and torn down), event polling, the frame clock, presenting to the default framebuffer,
// the ImGui frame, the GL error policy, the `--screenshot` capture and the `--exit-after-frames`
// exit of the smoke tests. A mode (the walkthrough viewer, the head-tracked immersive mode)
// only renders, presents through the loop's Presenter and draws its panel.
#include "presenter.hpp"
#include "window_session.hpp"

#include <glm/glm.hpp>

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace strata {

// One way of using the window. Each frame the loop calls update, render and drawPanel (inside
// the ImGui frame), swaps, then afterSwap.
class WindowMode {
public:
    virtual ~WindowMode() = default;
    // Once, before the first frame; `now` is the loop's clock (glfwGetTime, seconds).
    virtual void start(double now) { (void)now; }
    // The input since the last frame; `now` is this frame's start, `dt` the time since the last.
    virtual void update(double now, double dt, const CallbackInput& input) = 0;
    // Renders at the framebuffer size and shows the result through `presenter`.
    virtual void render(glm::ivec2 size, Presenter& presenter) = 0;
    // The panel over the presented frame. `lastGlError` is the last GL error the loop saw (empty
    // when none).
    virtual void drawPanel(glm::ivec2 size, const std::string& lastGlError) = 0;
    // The swap has returned: the frame is on its way to the display.
    virtual void afterSwap() {}
    // The smoke test's last frame, after the `screenshot:` line: what else the test reads.
    virtual void reportLastFrame() {}
    // The loop has ended (window closed or the smoke test done).
    virtual void stop() {}
};

struct WindowLoopOptions {
    int width = 1280, height = 800;
    std::string title;
    std::string name = "view";   // names the command in error messages
    // Smoke testing: exit after this many frames (0 = run until closed); with `screenshot`, save
    // the window as shown on the last frame and print its statistics.
    int exitAfterFrames = 0;
    std::optional<std::filesystem::path> screenshot;
};

// Makes the mode once the window's GL context is current.
using WindowModeFactory = std::function<std::unique_ptr<WindowMode>(GLFWwindow* window)>;

// Opens the window, makes the mode and runs until the window closes or the smoke test is done;
// the mode's GL objects die before the context. Returns the exit status (0). Throws
// std::runtime_error when no window can be opened, and in a smoke test on any GL error.
int runWindowLoop(const WindowLoopOptions& options, const WindowModeFactory& makeMode);

}  // namespace strata
