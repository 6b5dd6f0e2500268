#version 450 core
// Resolve of the array-based buffers: each pixel's fragments lie in one contiguous range of
// `entries` (fab and kbuffer: K slots at pixel * K; sbuffer: its scanned region). The range is
// sorted front to back by (depth, object id, primitive id), exactly like the A-buffer, and
// composited over the opaque colour, then the tail (if any) behind it. Up to LOCAL_CAPACITY
// fragments are insertion-sorted in registers; longer ranges are walked by repeated selection.
#include "bindings.glsl"
#include "entry.glsl"
#include "tail_resolve.glsl"

#ifndef LOCAL_CAPACITY
#define LOCAL_CAPACITY 64
#endif

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
#endif
}

bool before(uint a, uint b) {
    FragmentEntry ea = entries[a];
    FragmentEntry eb = entries[b];
    if (ea.depth != eb.depth) return ea.depth > eb.depth;
    if (ea.objectId != eb.objectId) return ea.objectId < eb.objectId;
    return ea.primitiveId < eb.primitiveId;
}

void composite(uint e, inout vec3 color, inout float transmittance) {
    vec2 rg = unpackHalf2x16(entries[e].colorRG);
    vec2 ba = unpackHalf2x16(entries[e].colorBA);
    color += transmittance * ba.y * vec3(rg, ba.x);
    transmittance *= 1.0 - ba.y;
}

layout(location = 0) out vec4 outColor;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec3 opaque = texelFetch(uOpaqueColor, pixel, 0).rgb;
    uint first, count;
    pixelRange(pixel, first, count);

    vec3 color = vec3(0.0);
    float transmittance = 1.0;
    if (count <= LOCAL_CAPACITY) {
        uint local[LOCAL_CAPACITY];
        for (uint i = 0u; i < count; ++i) {
            uint e = first + i;
            uint j = i;
            // Not `while (j > 0u && before(e, local[j - 1u]))`: on llvmpipe that form sorted
            // wrongly in ll's resolve (the local[-1] operand seems not to be skipped).
            while (j > 0u) {
                if (!before(e, local[j - 1u])) break;
                local[j] = local[j - 1u];
                j--;
            }
            local[j] = e;
        }
        for (uint i = 0u; i < count; ++i) composite(local[i], color, transmittance);
    } else {
        // Selection walk: each step finds the first entry after the previous one in key order.
        uint previous = 0xFFFFFFFFu;
        for (uint step = 0u; step < count; ++step) {
            uint best = 0xFFFFFFFFu;
            for (uint e = first; e < first + count; ++e) {
                if (previous != 0xFFFFFFFFu && !before(previous, e)) continue;
                if (best == 0xFFFFFFFFu || before(e, best)) best = e;
            }
            if (best == 0xFFFFFFFFu) break;
            composite(best, color, transmittance);
            previous = best;
        }
    }
    compositeTail(pixel, color, transmittance);
    outColor = vec4(color + transmittance * opaque, 1.0);
}
