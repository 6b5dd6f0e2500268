#version 450 core
// FAB store pass (FreePipe-style fixed-size arrays): each pixel owns K consecutive entries and a
// per-pixel counter; a fragment takes slot imageAtomicAdd(counter) if it is below K. The counter
// keeps running past K, so the resolve knows how many overflowed (counter - K). FAB keeps the
// FIRST K fragments to arrive, not the nearest; what overflows is dropped or goes to the tail.
#include "surface.glsl"
#include "entry.glsl"
#include "oit/fragment_color.glsl"
#include "tail_store.glsl"
#include "oit/subgroup_counter.glsl"

layout(early_fragment_tests) in;
layout(binding = BIND_PIXEL_COUNTS, r32ui) uniform coherent uimage2D uCounts;
layout(binding = BIND_COUNTERS, offset = 0) uniform atomic_uint uStored;
layout(binding = BIND_COUNTERS, offset = 4) uniform atomic_uint uOverflowed;
uniform uint uWidth;
uniform uint uCapacity;

void main() {
    StoredColor fragmentColor = storedSurfaceColor();
    vec4 c = fragmentColor.scalar;
    uvec2 words = fragmentColor.words;
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    uint slot = imageAtomicAdd(uCounts, pixel, 1u);
    if (slot < uCapacity) {
        uint index = (uint(pixel.y) * uWidth + uint(pixel.x)) * uCapacity + slot;
        entries[index] = makeEntry(gl_FragCoord.z, uObjectId, uint(gl_PrimitiveID), words);
        subgroupCounterIncrement(uStored);
        tailNone();
    } else {
        subgroupCounterIncrement(uOverflowed);
        tailAdd(c);
    }
}
