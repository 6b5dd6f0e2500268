#include "window_loop.hpp"

#include "window_capture.hpp"

#include "gl/debug.hpp"
#include "io/interrupt.hpp"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <utility>

namespace strata {
namespace {

void drawImGui(WindowMode& mode, glm::ivec2 size, const std::string& lastGlError) {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    mode.drawPanel(size, lastGlError);
    ImGui::Render();
    glViewport(0, 0, size.x, size.y);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

// --screenshot: the whole window as shown, panel included, and the statistics the smoke tests
// assert on (`scene` is the window read before the panel was drawn).
void saveScreenshot(const std::filesystem::path& path, const WindowPixels& scene, glm::ivec2 size) {
    WindowPixels window = readWindow(size);
    writeWindowPng(path, window);
    std::printf("screenshot: %s %dx%d distinct_colors=%zu scene_colors=%zu panel_pixels=%zu\n",
                path.string().c_str(), window.width, window.height, distinctColors(window),
                distinctColors(scene), changedPixels(scene, window));
}

void runLoop(GLFWwindow* window, WindowMode& mode, Presenter& presenter, const WindowLoopOptions& options) {
    const bool smokeTest = options.exitAfterFrames > 0;
    std::string lastGlError;
    std::uint64_t frames = 0;
    double last = glfwGetTime();
    mode.start(last);
    // Ctrl-C in the terminal closes the window as its close button would (recordings are saved).
    while (!glfwWindowShouldClose(window) && !interruptSignal()) {
        glfwPollEvents();
        const double now = glfwGetTime();
        const double dt = now - last;
        last = now;
        const CallbackInput input = std::exchange(callbackInput(), {});
        glm::ivec2 size;
        glfwGetFramebufferSize(window, &size.x, &size.y);
        if (size.x <= 0 || size.y <= 0) {  // minimised
            glfwWaitEvents();
            continue;
        }
        mode.update(now, dt, input);
        mode.render(size, presenter);
        ++frames;

        const bool lastFrame = smokeTest && frames >= std::uint64_t(options.exitAfterFrames);
        WindowPixels scene;
        if (lastFrame && options.screenshot) scene = readWindow(size);
        drawImGui(mode, size, lastGlError);
        // A smoke test fails on any GL error; interactively the panel shows the last one.
        if (auto errors = gl::takeErrors(); !errors.empty()) {
            if (smokeTest) throw std::runtime_error(options.name + ": GL error: " + errors.front());
            lastGlError = errors.back();
        }
        if (lastFrame) {
            if (options.screenshot) saveScreenshot(*options.screenshot, scene, size);
            mode.reportLastFrame();
            break;
        }
        glfwSwapBuffers(window);
        mode.afterSwap();
    }
    mode.stop();
}

}  // namespace

int runWindowLoop(const WindowLoopOptions& options, const WindowModeFactory& makeMode) {
    WindowSession session(options.width, options.height, options.title);
    {
        // GL objects die before the context does.
        Presenter presenter;
        std::unique_ptr<WindowMode> mode = makeMode(session.window());
        runLoop(session.window(), *mode, presenter, options);
    }
    std::fflush(stdout);
    return 0;
}

}  // namespace strata
