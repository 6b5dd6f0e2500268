// checkFrameSize against given device limits: a size the device cannot back is refused with
// the size and the limit it breaks, before anything is allocated. (The same against a real
// context: frame_size_gl_test.cpp.)
#include "render/frame_size.hpp"

#include <doctest/doctest.h>

#include <stdexcept>
#include <string>

using namespace strata;

namespace {

std::string errorOf(glm::ivec2 size, const DeviceLimits& limits) {
    try {
        checkFrameSize(size, limits);
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "(no error)";
}

}  // namespace

TEST_CASE("frame size: within every limit passes; each limit broken is named with the size") {
    DeviceLimits l;
    l.maxTextureSize = 16384;
    l.maxRenderbufferSize = 8192;
    l.maxViewport[0] = 16384;
    l.maxViewport[1] = 4096;
    l.availableBytes = std::uint64_t(1) << 30;
    l.memorySource = "available memory";
    CHECK(errorOf({4096, 4096}, l) == "(no error)");  // 4096^2 * 52 bytes = 832 MiB < 1 GiB
    CHECK(errorOf({8193, 16}, l) == "size 8193x16: over the device's GL_MAX_RENDERBUFFER_SIZE of 8192");
    CHECK(errorOf({16, 4097}, l) == "size 16x4097: over the device's GL_MAX_VIEWPORT_DIMS height of 4096");
    l.maxRenderbufferSize = 16384;
    CHECK(errorOf({16385, 1}, l) == "size 16385x1: over the device's GL_MAX_TEXTURE_SIZE of 16384");
    // 8192 x 4096 x 52 bytes = 1.6 GiB of frame against 1 GiB.
    CHECK(errorOf({8192, 4096}, l) == "size 8192x4096: a frame needs at least 1.6 GiB, over the 1 GiB of available memory");
    l.availableBytes = 0;  // unknown: not checked
    CHECK(errorOf({8192, 4096}, l) == "(no error)");
}
