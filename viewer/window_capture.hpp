#pragma once
// Reading the window back: the default framebuffer's pixels as the user sees them (sRGB bytes,
// ImGui panel included), written as PNG, and two plain statistics the smoke test asserts on
// (how many distinct colours, how many pixels the panel changed).
#include "image/image.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <filesystem>
#include <vector>

namespace strata {

struct WindowPixels {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;  // sRGB-encoded bytes, row 0 = bottom (GL order)
};

// glReadPixels of the default framebuffer's back buffer (call before swapping).
WindowPixels readWindow(glm::ivec2 size);

// Writes the bytes as they are (no second sRGB encoding) to an 8-bit RGB PNG, top row first,
// through writeFileAtomically (io/atomic_file.hpp). Throws std::runtime_error naming the file.
void writeWindowPng(const std::filesystem::path& path, const WindowPixels& pixels);

// A linear-RGB frame (FrameRenderer::readOutput) encoded to sRGB bytes, rounded to nearest.
WindowPixels encodeSrgb(const Image& image);

std::size_t distinctColors(const WindowPixels& pixels);
// Pixels whose RGB differs between two reads of the same size.
std::size_t changedPixels(const WindowPixels& before, const WindowPixels& after);

}  // namespace strata
