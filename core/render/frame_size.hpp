#pragma once
// Whether the device can back a frame of a given size, asked before anything is allocated.
// A size the driver cannot allocate otherwise fails late and vaguely ("framebuffer incomplete
// (status 0x...)" after the scene is uploaded) or takes the machine's memory with it.
#include <glm/glm.hpp>

#include <cstdint>
#include <string>

namespace strata {

// Bytes per pixel of one frame at the least: the frame targets (RGBA32F opaque and output
// colour, 32-bit depth: frame_targets.hpp) and the RGBA32F read-back image on the CPU.
inline constexpr std::uint64_t kFrameBytesPerPixel = 16 + 16 + 4 + 16;

struct DeviceLimits {
    int maxTextureSize = 0;       // GL_MAX_TEXTURE_SIZE
    int maxRenderbufferSize = 0;  // GL_MAX_RENDERBUFFER_SIZE
    int maxViewport[2] = {0, 0};  // GL_MAX_VIEWPORT_DIMS
    // Memory a frame may take: the GPU's free memory where the driver tells it
    // (GL_NVX_gpu_memory_info, GL_ATI_meminfo), else the machine's available memory (llvmpipe
    // and other drivers that allocate from system memory). 0: unknown, not checked.
    std::uint64_t availableBytes = 0;
    std::string memorySource;     // where availableBytes came from, for the message
};

// Needs a current GL context.
DeviceLimits queryDeviceLimits();

// Throws std::runtime_error "size WxH: <which limit, with its value>" when `size` exceeds a
// dimension limit or its estimated memory (kFrameBytesPerPixel per pixel) exceeds the
// available memory. Pure: tested without a context.
void checkFrameSize(glm::ivec2 size, const DeviceLimits& limits);
// The same against the current context's limits.
void checkFrameSize(glm::ivec2 size);

}  // namespace strata
