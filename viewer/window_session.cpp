#include "window_session.hpp"

#include "gl/context.hpp"
#include "gl/debug.hpp"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <cstdlib>
#include <stdexcept>

namespace strata {
namespace {

std::string g_glfwError;  // GLFW's last error description, for the one-line messages we throw

void onGlfwError(int, const char* description) { g_glfwError = description ? description : "unknown error"; }
void onScroll(GLFWwindow*, double, double y) { callbackInput().scroll += float(y); }
void onKey(GLFWwindow*, int key, int, int action, int) {
    if (action == GLFW_PRESS) callbackInput().pressed.push_back(key);
}

bool displayVariableSet() {
    const char* x11 = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    return (x11 && *x11) || (wayland && *wayland);
}

}  // namespace

CallbackInput& callbackInput() {
    static CallbackInput input;
    return input;
}

bool glfwUsable() {
    if (!displayVariableSet()) return false;
    glfwSetErrorCallback(onGlfwError);
    if (!glfwInit()) return false;
    glfwTerminate();
    return true;
}

GlfwLibrary::GlfwLibrary() {
    if (!displayVariableSet())
        throw std::runtime_error("view: no display (DISPLAY and WAYLAND_DISPLAY are unset); "
                                 "`strata render` makes images without one");
    glfwSetErrorCallback(onGlfwError);
    if (!glfwInit()) throw std::runtime_error("view: cannot initialise GLFW: " + g_glfwError);
}

GlfwLibrary::~GlfwLibrary() { glfwTerminate(); }

WindowPtr openWindow(int width, int height, const std::string& title) {
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, GLFW_TRUE);
    glfwWindowHint(GLFW_SRGB_CAPABLE, GLFW_FALSE);  // present.frag encodes; nothing else may
    WindowPtr window(glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr));
    if (!window)
        throw std::runtime_error("view: cannot create a window with an OpenGL 4.5 core context: " + g_glfwError);
    glfwMakeContextCurrent(window.get());
    glfwSwapInterval(1);
    gl::installDebugCallback();
    gl::requireCoreFeatures();
    glfwSetScrollCallback(window.get(), onScroll);
    glfwSetKeyCallback(window.get(), onKey);
    return window;
}

ImGuiSession::ImGuiSession(GLFWwindow* window) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the working directory
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForOpenGL(window, true);  // chains to the callbacks openWindow installed
    ImGui_ImplOpenGL3_Init("#version 450 core");
}

ImGuiSession::~ImGuiSession() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

}  // namespace strata
