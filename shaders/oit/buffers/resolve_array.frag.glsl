#version 450 core
// Resolve of the array-based buffers: each pixel's fragments lie in one contiguous range of
// `entries` (fab and kbuffer: K slots at pixel * K; sbuffer: its scanned region). The range is
// composited over the opaque colour in the exact order of ordered_composite.glsl, like the
// A-buffer, then the tail (if any) behind it.
#include "bindings.h"
#include "entry.glsl"
#include "tail_resolve.glsl"
#include "oit/packed_color.glsl"

layout(binding = BIND_OPAQUE_COLOR) uniform sampler2D uOpaqueColor;
uniform uint uWidth;
uniform uint uCapacity;  // fab, kbuffer: slots per pixel

#if defined(LAYOUT_FAB)
layout(binding = BIND_PIXEL_COUNTS, r32ui) uniform coherent uimage2D uCounts;
#elif defined(LAYOUT_KBUFFER)
layout(std430, binding = BIND_DEPTH_KEYS) coherent buffer DepthKeys { uint depthKeys[]; };
#elif defined(LAYOUT_SBUFFER)
// After the store pass each offset has advanced by its pixel's count: it is the region's end.
layout(std430, binding = BIND_PIXEL_OFFSETS) coherent buffer PixelOffsets { uint offsets[]; };
uniform uint uBase;
#else
#error "define LAYOUT_FAB, LAYOUT_KBUFFER or LAYOUT_SBUFFER"
#endif

// The pixel's range [first, first + count).
void pixelRange(ivec2 pixel, out uint first, out uint count) {
    uint index = uint(pixel.y) * uWidth + uint(pixel.x);
#if defined(LAYOUT_FAB)
    first = index * uCapacity;
    count = min(imageLoad(uCounts, pixel).r, uCapacity);
#elif defined(LAYOUT_KBUFFER)
    // Keys are kept sorted nearest first; 0 marks the first empty slot.
    first = index * uCapacity;
    count = 0u;
    while (count < uCapacity && depthKeys[first + count] != 0u) count++;
#else
    first = index == 0u ? 0u : offsets[index - 1u];
    count = offsets[index] - first;
    // Banded (sbuffer.cpp): entries hold the current band only, from its first entry uBase; a
    // row that overflowed its band holds fewer than it counted.
    first -= uBase;
    count = min(count, uCapacity > first ? uCapacity - first : 0u);
#endif
}

uint gFirst, gEnd;  // the pixel's range [gFirst, gEnd)

float fragmentDepth(uint i) { return entries[i].depth; }
uint fragmentObject(uint i) { return entries[i].objectId; }
uint fragmentPrimitive(uint i) { return entries[i].primitiveId; }

void compositeFragment(uint e, inout vec3 color, inout Transmittance transmittance) {
    compositePacked(entries[e].colorRG, entries[e].colorBA, color, transmittance);
}

void compositeFragmentInFront(uint e, inout vec3 color, inout Transmittance transmittance) {
    compositePackedInFront(entries[e].colorRG, entries[e].colorBA, color, transmittance);
}
#define LIST_WALK_IN_ORDER  // ordered_composite.glsl: a range already in depth order composites as read

#define FOR_EACH_FRAGMENT(i) for (uint i = gFirst; i < gEnd; ++i)
#include "oit/ordered_composite.glsl"

layout(location = 0) out vec4 outColor;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec3 opaque = texelFetch(uOpaqueColor, pixel, 0).rgb;
    uint count;
    pixelRange(pixel, gFirst, count);
    gEnd = gFirst + count;
    vec3 color = vec3(0.0);
    Transmittance transmittance = Transmittance(1.0);
    compositeInDepthOrder(color, transmittance);
    compositeTail(pixel, color, transmittance);
    outColor = vec4(color + transmittance * opaque, 1.0);
}
