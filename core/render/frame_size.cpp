#include "render/frame_size.hpp"

#include "io/bounded_read.hpp"

#include <epoxy/gl.h>

#include <cstring>
#include <stdexcept>

#include <unistd.h>

namespace strata {
namespace {

// GL_NVX_gpu_memory_info and GL_ATI_meminfo enums (not in every header), kilobytes.
constexpr GLenum kNvxCurrentAvailableKb = 0x9049;
constexpr GLenum kAtiTextureFreeMemory = 0x87FC;

}  // namespace

DeviceLimits queryDeviceLimits() {
    DeviceLimits l;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &l.maxTextureSize);
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &l.maxRenderbufferSize);
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, l.maxViewport);
    if (epoxy_has_gl_extension("GL_NVX_gpu_memory_info")) {
        GLint kb = 0;
        glGetIntegerv(kNvxCurrentAvailableKb, &kb);
        l.availableBytes = std::uint64_t(kb) * 1024;
        l.memorySource = "free GPU memory";
    } else if (epoxy_has_gl_extension("GL_ATI_meminfo")) {
        GLint kb[4] = {0, 0, 0, 0};
        glGetIntegerv(kAtiTextureFreeMemory, kb);
        l.availableBytes = std::uint64_t(kb[0]) * 1024;
        l.memorySource = "free GPU memory";
    } else {
        long pages = ::sysconf(_SC_AVPHYS_PAGES), pageSize = ::sysconf(_SC_PAGESIZE);
        if (pages > 0 && pageSize > 0) {
            l.availableBytes = std::uint64_t(pages) * std::uint64_t(pageSize);
            l.memorySource = "available memory";
        }
    }
    while (glGetError() != GL_NO_ERROR) {}  // an enum the driver did not know after all
    return l;
}

void checkFrameSize(glm::ivec2 size, const DeviceLimits& limits) {
    const std::string name = "size " + std::to_string(size.x) + "x" + std::to_string(size.y);
    auto check = [&](int value, int limit, const char* what) {
        if (limit > 0 && value > limit)
            throw std::runtime_error(name + ": over the device's " + what + " of " + std::to_string(limit));
    };
    check(std::max(size.x, size.y), limits.maxTextureSize, "GL_MAX_TEXTURE_SIZE");
    check(std::max(size.x, size.y), limits.maxRenderbufferSize, "GL_MAX_RENDERBUFFER_SIZE");
    check(size.x, limits.maxViewport[0], "GL_MAX_VIEWPORT_DIMS width");
    check(size.y, limits.maxViewport[1], "GL_MAX_VIEWPORT_DIMS height");
    const std::uint64_t need = std::uint64_t(size.x) * std::uint64_t(size.y) * kFrameBytesPerPixel;
    if (limits.availableBytes > 0 && need > limits.availableBytes)
        throw std::runtime_error(name + ": a frame needs at least " + formatBytes(need) + ", over the " +
                                 formatBytes(limits.availableBytes) + " of " + limits.memorySource);
}

void checkFrameSize(glm::ivec2 size) {
    checkFrameSize(size, queryDeviceLimits());
    // A proxy texture asks the driver whether it could allocate the frame's largest format at
    // this size, without allocating it: llvmpipe, for one, refuses textures over 1 GiB although
    // its GL_MAX_TEXTURE_SIZE is 16384.
    while (glGetError() != GL_NO_ERROR) {}
    glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA32F, size.x, size.y, 0, GL_RGBA, GL_FLOAT, nullptr);
    GLint width = 0;
    glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &width);
    while (glGetError() != GL_NO_ERROR) {}
    if (width == 0)
        throw std::runtime_error("size " + std::to_string(size.x) + "x" + std::to_string(size.y) +
                                 ": the driver cannot allocate an RGBA32F frame target of this size (" +
                                 formatBytes(std::uint64_t(size.x) * std::uint64_t(size.y) * 16) + ")");
}

}  // namespace strata
