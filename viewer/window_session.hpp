#pragma once
// The window side of `strata view`: GLFW with an OpenGL 4.5 core debug context, Dear ImGui on
// top of it, and the input that only arrives through callbacks (wheel, key presses).
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
// shader encodes) and the input callbacks installed. Throws std::runtime_error with GLFW's reason.
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

}  // namespace strata
