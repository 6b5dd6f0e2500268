#pragma once
// The window side of `strata view`: GLFW with an OpenGL 4.5 core debug context, Dear ImGui on
// top of it, and the input that only arrives through callbacks (wheel, key presses). Every
// window mode runs inside one WindowSession (viewer/window_loop.hpp).
#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <memory>
#include <string>
#include <vector>

namespace strata {

// Filled by the callbacks (which ImGui's own callbacks chain to), drained by the viewer each frame.
struct CallbackInput {
    float scroll = 0.0f;        // wheel steps since last drained
    std::vector<int> pressed;   // GLFW keys pressed since last drained
};
CallbackInput& callbackInput();

// DISPLAY or WAYLAND_DISPLAY set and glfwInit() succeeds (GLFW is terminated again).
bool glfwUsable();

// glfwInit/glfwTerminate. Throws std::runtime_error (one line) without a display or when GLFW
// cannot initialise.
class GlfwLibrary {
public:
    GlfwLibrary();
    ~GlfwLibrary();
    GlfwLibrary(const GlfwLibrary&) = delete;
    GlfwLibrary& operator=(const GlfwLibrary&) = delete;
};

struct WindowDeleter {
    void operator()(GLFWwindow* w) const { glfwDestroyWindow(w); }
};
using WindowPtr = std::unique_ptr<GLFWwindow, WindowDeleter>;

// A window with a current OpenGL 4.5 core debug context (no sRGB framebuffer: the present
// shader encodes), vsync on, GL errors recorded (gl::installDebugCallback), the core features
// checked and the input callbacks installed. Throws std::runtime_error with GLFW's reason or the
// missing feature.
WindowPtr openWindow(int width, int height, const std::string& title);

// Dear ImGui on the window (GLFW + OpenGL 3 backends); create after openWindow so ImGui's
// callbacks chain to ours. No imgui.ini is written.
class ImGuiSession {
public:
    explicit ImGuiSession(GLFWwindow* window);
    ~ImGuiSession();
    ImGuiSession(const ImGuiSession&) = delete;
    ImGuiSession& operator=(const ImGuiSession&) = delete;
};

// GLFW, the window and ImGui, set up in that order and torn down in reverse. Whatever owns GL
// objects must be destroyed before the session, while the context still exists.
class WindowSession {
public:
    WindowSession(int width, int height, const std::string& title)
        : window_(openWindow(width, height, title)), imgui_(window_.get()) {}
    GLFWwindow* window() const { return window_.get(); }

private:
    GlfwLibrary glfw_;
    WindowPtr window_;
    ImGuiSession imgui_;
};

}  // namespace strata
