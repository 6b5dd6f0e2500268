#include "window_capture.hpp"

#include "image/image.hpp"
#include "io/atomic_file.hpp"

#include <epoxy/gl.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace strata {

WindowPixels readWindow(glm::ivec2 size) {
    WindowPixels p;
    p.width = size.x;
    p.height = size.y;
    p.rgba.resize(std::size_t(size.x) * std::size_t(size.y) * 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, size.x, size.y, GL_RGBA, GL_UNSIGNED_BYTE, p.rgba.data());
    return p;
}

void writeWindowPng(const std::filesystem::path& path, const WindowPixels& pixels) {
    // Written with OpenImageIO directly: the bytes are already what the screen shows, so they
    // must not pass through a float image and a second encoding.
    if (path.extension() != ".png") throw std::runtime_error(path.string() + ": screenshots are written as .png");
    writeFileAtomically(path, [&](const std::filesystem::path& temporary) {
        auto out = OIIO::ImageOutput::create(temporary.string());
        if (!out) throw std::runtime_error("no PNG writer: " + OIIO::geterror());
        OIIO::ImageSpec spec(pixels.width, pixels.height, 3, OIIO::TypeDesc::UINT8);
        spec.attribute("oiio:ColorSpace", "sRGB");
        // RGB of the RGBA rows, last (top) row first: a negative y stride flips without a copy.
        const std::ptrdiff_t row = std::ptrdiff_t(pixels.width) * 4;
        const std::uint8_t* top = pixels.rgba.data() + row * (pixels.height - 1);
        bool ok = out->open(temporary.string(), spec) &&
                  out->write_image(OIIO::TypeDesc::UINT8, top, 4, -row, OIIO::AutoStride) && out->close();
        if (!ok) throw std::runtime_error("cannot write screenshot: " + out->geterror());
    });
}

WindowPixels encodeSrgb(const Image& image) {
    WindowPixels p;
    p.width = image.width;
    p.height = image.height;
    p.rgba.resize(image.rgba.size());
    for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
        for (std::size_t c = 0; c < 3; ++c)
            p.rgba[i + c] = std::uint8_t(std::lround(linearToSrgb(image.rgba[i + c]) * 255.0f));
        p.rgba[i + 3] = 255;
    }
    return p;
}

namespace {
std::uint32_t rgbKey(const std::uint8_t* p) { return std::uint32_t(p[0]) << 16 | std::uint32_t(p[1]) << 8 | p[2]; }
}  // namespace

std::size_t distinctColors(const WindowPixels& pixels) {
    std::vector<std::uint32_t> keys;
    keys.reserve(pixels.rgba.size() / 4);
    for (std::size_t i = 0; i < pixels.rgba.size(); i += 4) keys.push_back(rgbKey(&pixels.rgba[i]));
    std::sort(keys.begin(), keys.end());
    return std::size_t(std::unique(keys.begin(), keys.end()) - keys.begin());
}

std::size_t changedPixels(const WindowPixels& before, const WindowPixels& after) {
    if (before.width != after.width || before.height != after.height)
        throw std::logic_error("changedPixels: reads of different sizes");
    std::size_t n = 0;
    for (std::size_t i = 0; i < before.rgba.size(); i += 4)
        n += rgbKey(&before.rgba[i]) != rgbKey(&after.rgba[i]);
    return n;
}

}  // namespace strata
