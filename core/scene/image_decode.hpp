#pragma once
// Decodes a texture image (PNG, JPEG, and WebP where the installed OpenImageIO reads it) from
// bytes in memory to RGBA8, within limits checked from the header before any pixel is
// allocated: a side of at most kMaxImageSide texels and at most kMaxImageBytes decoded (a
// decompression bomb is refused). KTX2 is refused by name: Debian has no KTX2 library.
#include "scene/texture.hpp"

#include <cstddef>
#include <string>

namespace strata {

inline constexpr int kMaxImageSide = 16384;
inline constexpr std::size_t kMaxImageBytes = std::size_t(256) << 20;  // RGBA8 of one image

// Decodes `size` bytes; on failure returns false with `error` saying why in a few words (the
// caller names the file, the image and the material).
bool decodeImage(const unsigned char* bytes, std::size_t size, TextureImage& out, std::string& error);

}  // namespace strata
