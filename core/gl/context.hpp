#pragma once
// An OpenGL 4.5 core context without a window: EGL on Mesa's surfaceless platform (llvmpipe
// on a machine without a GPU) or, where that platform is absent, the EGL device platform
// (the NVIDIA driver). Rendering goes to framebuffer objects; nothing is presented.
#include <memory>
#include <string>

namespace strata::gl {

struct DeviceInfo {
    std::string vendor;
    std::string renderer;
    std::string version;

    // A software rasterizer (Mesa's llvmpipe or softpipe): the CPU shades, blends and takes the
    // atomics, so what is fast differs from a GPU's (gl/gpu_timer.cpp, oit/device_defaults.hpp).
    bool software() const;
};

// Reads GL_VENDOR/RENDERER/VERSION of the current context.
DeviceInfo currentDeviceInfo();

class HeadlessContext {
public:
    // Creates and makes current a 4.5 core debug context. Throws std::runtime_error with the
    // EGL step that failed.
    HeadlessContext();
    ~HeadlessContext();
    HeadlessContext(const HeadlessContext&) = delete;
    HeadlessContext& operator=(const HeadlessContext&) = delete;

    const std::string& platform() const { return platform_; }

private:
    void* display_ = nullptr;
    void* context_ = nullptr;
    std::string platform_;
};

// Checks the limits the techniques rely on (SSBO, image load/store, 32-bit float targets).
// Throws naming the missing feature.
void requireCoreFeatures();

}  // namespace strata::gl
