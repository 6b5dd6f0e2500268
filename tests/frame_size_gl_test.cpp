// checkFrameSize with the context's own limits (EGL; llvmpipe in CI).
#include "gl_test_support.hpp"
#include "render/frame_size.hpp"

#include <doctest/doctest.h>

#include <stdexcept>
#include <string>

using namespace strata;

TEST_CASE("frame size (GL): the device's limits are read, and a size past them is refused before allocating") {
    test::glContext();
    DeviceLimits limits = queryDeviceLimits();
    CHECK(limits.maxTextureSize >= 1024);  // GL 4.5 guarantees 16384; never less than 1024
    CHECK(limits.maxRenderbufferSize >= 1024);
    CHECK(limits.maxViewport[0] >= 1024);
    CHECK_NOTHROW(checkFrameSize({64, 64}));
    const int over = limits.maxTextureSize + 1;
    try {
        checkFrameSize({over, 1});
        FAIL("no error");
    } catch (const std::runtime_error& e) {
        CHECK(std::string(e.what()).rfind("size " + std::to_string(over) + "x1: over the device's ", 0) == 0);
    }
}
