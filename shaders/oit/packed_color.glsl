// A stored fragment's colour in two words, the layout of the A-buffer's nodes and the buffers'
// entries, and its composites: behind what is held (front to back) or in front of it.
//  - Scalar (the default): half2 (r, g) and half2 (b, alpha), colour not premultiplied.
//  - STRATA_RGB_TRANSMITTANCE adds a coloured filter's layout, flagged by bit 31 of word 1 (the
//    scalar layout's alpha, a half in [0, 1], never sets it): the premultiplied colour in RGB9E5
//    (GL's shared-exponent format: nine mantissa bits each, so each channel is within 2^-10 of
//    the largest, HDR highlights included) and the transmittance per channel as three 10-bit
//    unorms (within 1/2046). Every other fragment of such a scene keeps the scalar layout and its
//    precision (a 10-bit transmittance would shift 16 layers of one alpha by up to 0.8 %). The
//    same 8 bytes either way: a scene with coloured filters costs no memory more.
#ifndef STRATA_PACKED_COLOR_GLSL
#define STRATA_PACKED_COLOR_GLSL
#include "oit/transmittance.glsl"

#ifdef STRATA_RGB_TRANSMITTANCE
const uint kColoredFilter = 0x80000000u;  // word 1's flag

// GL 4.5 specification 8.5.2 (the RGB9_E5 encoding), with the exponent from frexp, which is
// exact where floor(log2(x)) can round up.
uint packRgb9e5(vec3 rgb) {
    const float kMax = 65408.0;  // (2^9 - 1) / 2^9 * 2^16
    vec3 c = clamp(rgb, vec3(0.0), vec3(kMax));
    float largest = max(c.r, max(c.g, c.b));
    int e;
    frexp(largest, e);                // largest = m 2^e, m in [0.5, 1): floor(log2) = e - 1
    int exponent = max(-16, e - 1) + 16;  // biased by 15, plus one
    float scale = exp2(float(exponent - 15 - 9));
    if (floor(largest / scale + 0.5) >= 512.0) {
        exponent += 1;
        scale *= 2.0;
    }
    uvec3 m = uvec3(floor(c / scale + 0.5));
    return m.r | (m.g << 9) | (m.b << 18) | (uint(exponent) << 27);
}

vec3 unpackRgb9e5(uint word) {
    uvec3 m = uvec3(word & 511u, (word >> 9) & 511u, (word >> 18) & 511u);
    return vec3(m) * exp2(float(int(word >> 27) - 15 - 9));
}

uint packUnorm3x10(vec3 t) {
    uvec3 q = uvec3(round(clamp(t, vec3(0.0), vec3(1.0)) * 1023.0));
    return q.r | (q.g << 10) | (q.b << 20);
}

vec3 unpackUnorm3x10(uint word) {
    return vec3(uvec3(word & 1023u, (word >> 10) & 1023u, (word >> 20) & 1023u)) / 1023.0;
}
#endif

// A stored fragment's premultiplied colour and what it lets through (its transmittance).
void unpackFragment(uint word0, uint word1, out vec3 premultiplied, out Transmittance passes) {
#ifdef STRATA_RGB_TRANSMITTANCE
    if ((word1 & kColoredFilter) != 0u) {
        premultiplied = unpackRgb9e5(word0);
        passes = unpackUnorm3x10(word1);
        return;
    }
#endif
    vec2 rg = unpackHalf2x16(word0);
    vec2 ba = unpackHalf2x16(word1);
    premultiplied = ba.y * vec3(rg, ba.x);
    passes = Transmittance(1.0 - ba.y);
}

// The fragment composited behind what `color` and `transmittance` hold (front to back).
void compositePacked(uint word0, uint word1, inout vec3 color, inout Transmittance transmittance) {
    vec3 c;
    Transmittance t;
    unpackFragment(word0, word1, c, t);
    color += transmittance * c;
    transmittance *= t;
}

// The same fragment composited IN FRONT of what `color` and `transmittance` hold (back to front):
// the composite of a list walked farthest first ends where compositePacked's, nearest first, does.
void compositePackedInFront(uint word0, uint word1, inout vec3 color, inout Transmittance transmittance) {
    vec3 c;
    Transmittance t;
    unpackFragment(word0, word1, c, t);
    color = c + t * color;
    transmittance *= t;
}
#endif
