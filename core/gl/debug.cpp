#include "gl/debug.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>

#include <epoxy/gl.h>

#include <mutex>
#include <stdexcept>
#include <utility>

namespace strata::gl {
namespace {

std::mutex g_mutex;
std::vector<std::string> g_pending;
std::size_t g_total = 0;

void record(std::string message) {
    std::lock_guard lock(g_mutex);
    ++g_total;
    if (g_pending.size() < 64) g_pending.push_back(std::move(message));
}

// STRATA_DEBUG_PRINT_GL_MESSAGES=1: every message the driver sends (performance notes, shader
// recompiles, texture state warnings) goes to stderr, the first 400, for a GPU diagnostic run.
void printMessage(GLenum type, GLuint id, GLenum severity, GLsizei length, const GLchar* message) {
    static const bool on = debugSwitch("STRATA_DEBUG_PRINT_GL_MESSAGES");
    static int printed = 0;
    if (!on || printed >= 400) return;
    ++printed;
    const int shown = length > 0 ? int(length) : int(std::strlen(message));  // a length < 0: NUL-ended
    std::fprintf(stderr, "[strata debug] GL message type 0x%x id %u severity 0x%x: %.*s\n", type, id, severity,
                 shown, message);
}

void GLAPIENTRY onDebugMessage(GLenum, GLenum type, GLuint id, GLenum severity, GLsizei length,
                               const GLchar* message, const void*) {
    printMessage(type, id, severity, length, message);
    // Only errors and undefined behaviour count; performance notes from the driver do not.
    bool isError = type == GL_DEBUG_TYPE_ERROR || type == GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR;
    if (!isError || severity == GL_DEBUG_SEVERITY_NOTIFICATION) return;
    record("[" + std::to_string(id) + "] " + std::string(message, length > 0 ? std::size_t(length) : 0));
}

const char* errorName(GLenum e) {
    switch (e) {
        case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
        case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
        case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
        case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
        case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
        default: return "GL error";
    }
}

}  // namespace

void installDebugCallback() {
    if (!epoxy_has_gl_extension("GL_KHR_debug") && epoxy_gl_version() < 43) return;
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(onDebugMessage, nullptr);
    glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
}

std::vector<std::string> takeErrors() {
    for (GLenum e = glGetError(); e != GL_NO_ERROR; e = glGetError()) record(errorName(e));
    std::lock_guard lock(g_mutex);
    return std::exchange(g_pending, {});
}

std::size_t errorCount() {
    std::lock_guard lock(g_mutex);
    return g_total;
}

void checkGl(const char* where) {
    auto errors = takeErrors();
    if (errors.empty()) return;
    std::string message = std::string("GL error at ") + where + ": " + errors.front();
    if (errors.size() > 1) message += " (+" + std::to_string(errors.size() - 1) + " more)";
    throw std::runtime_error(message);
}

bool debugSwitch(const char* name) {
    const char* env = std::getenv(name);
    return env && std::string(env) == "1";
}

}  // namespace strata::gl
