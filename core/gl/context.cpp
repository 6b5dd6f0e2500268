#include "gl/context.hpp"
#include "gl/program_pool.hpp"

#include "gl/debug.hpp"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace strata::gl {
namespace {

std::string eglErrorText(const char* step) {
    char buffer[96];
    std::snprintf(buffer, sizeof buffer, "EGL %s failed (0x%04x)", step, unsigned(eglGetError()));
    return buffer;
}

// Surfaceless first (Mesa), then the device platform (NVIDIA's EGL), then the default display.
EGLDisplay openDisplay(std::string& platform) {
    const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    std::string ext = clientExtensions ? clientExtensions : "";
    if (ext.find("EGL_MESA_platform_surfaceless") != std::string::npos) {
        EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (d != EGL_NO_DISPLAY && eglInitialize(d, nullptr, nullptr)) { platform = "surfaceless"; return d; }
    }
    if (ext.find("EGL_EXT_platform_device") != std::string::npos) {
        EGLDeviceEXT devices[8];
        EGLint count = 0;
        if (eglQueryDevicesEXT(8, devices, &count) && count > 0) {
            for (EGLint i = 0; i < count; ++i) {
                EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
                if (d != EGL_NO_DISPLAY && eglInitialize(d, nullptr, nullptr)) { platform = "device"; return d; }
            }
        }
    }
    EGLDisplay d = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    if (d == EGL_NO_DISPLAY || !eglInitialize(d, nullptr, nullptr))
        throw std::runtime_error(eglErrorText("display initialisation"));
    platform = "default";
    return d;
}

}  // namespace

HeadlessContext::HeadlessContext() {
    EGLDisplay display = openDisplay(platform_);
    display_ = display;
    if (!eglBindAPI(EGL_OPENGL_API)) throw std::runtime_error(eglErrorText("eglBindAPI(OpenGL)"));

    const EGLint configAttributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint configCount = 0;
    if (!eglChooseConfig(display, configAttributes, &config, 1, &configCount) || configCount == 0)
        config = nullptr;  // EGL_KHR_no_config_context: surfaceless needs no config

    // STRATA_DEBUG_NO_DEBUG_CONTEXT=1: a context without the debug flag (docs/gpu-h100.md's
    // group 2 experiments; errors are then seen through glGetError only).
    const EGLint debugFlag = debugSwitch("STRATA_DEBUG_NO_DEBUG_CONTEXT") ? EGL_FALSE : EGL_TRUE;
    const EGLint contextAttributes[] = {
        EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
        EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
        EGL_CONTEXT_OPENGL_DEBUG, debugFlag, EGL_NONE};
    EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, contextAttributes);
    if (context == EGL_NO_CONTEXT)
        throw std::runtime_error(eglErrorText("OpenGL 4.5 core context creation"));
    context_ = context;
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context))
        throw std::runtime_error(eglErrorText("eglMakeCurrent (surfaceless)"));
    installDebugCallback();
    requireCoreFeatures();
}

HeadlessContext::~HeadlessContext() {
    auto display = static_cast<EGLDisplay>(display_);
    if (!display) return;
    releaseProgramPool();  // its programs die with the context; a next context starts afresh
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (context_) eglDestroyContext(display, static_cast<EGLContext>(context_));
    eglTerminate(display);
}

bool DeviceInfo::software() const {
    return renderer.find("llvmpipe") != std::string::npos || renderer.find("softpipe") != std::string::npos;
}

DeviceInfo currentDeviceInfo() {
    auto str = [](GLenum e) {
        const auto* s = reinterpret_cast<const char*>(glGetString(e));
        return std::string(s ? s : "unknown");
    };
    return {str(GL_VENDOR), str(GL_RENDERER), str(GL_VERSION)};
}

void requireCoreFeatures() {
    if (epoxy_gl_version() < 45)
        throw std::runtime_error("OpenGL 4.5 core is required, the context offers " +
                                 std::to_string(epoxy_gl_version() / 10) + "." +
                                 std::to_string(epoxy_gl_version() % 10));
    GLint bits = 0;
    glGetQueryiv(GL_TIMESTAMP, GL_QUERY_COUNTER_BITS, &bits);
    if (bits == 0) throw std::runtime_error("timer queries are not supported by this context");
}

}  // namespace strata::gl
