#pragma once
// Accumulation precision: the `precision` setting (precisionSetting in settings.hpp) of every technique that blends into (or
// stores colour in) float targets of its own. 16 bits per channel (RGBA16F: half the memory and
// bandwidth, a 10-bit mantissa, largest value 65504) or 32 (RGBA32F). Depth targets are never
// affected: they stay 32-bit float whatever this says.

#include <epoxy/gl.h>

#include <cstdint>

namespace strata {

inline bool isHalf(int bits) { return bits < 24; }

// GL_RGBA16F / GL_RGBA32F.
inline GLenum rgbaFloatFormat(int bits) { return isHalf(bits) ? GL_RGBA16F : GL_RGBA32F; }
// GL_R16F / GL_R32F.
inline GLenum redFloatFormat(int bits) { return isHalf(bits) ? GL_R16F : GL_R32F; }
// Bytes per texel of a float target with `channels` channels.
inline std::uint64_t floatTexelBytes(int bits, int channels) {
    return std::uint64_t(channels) * (isHalf(bits) ? 2u : 4u);
}

}  // namespace strata
