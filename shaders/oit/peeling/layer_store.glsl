// Appends the current fragment to its pixel's layer storage (layer_storage.glsl), counting it
// in the pass's atomic counters, whose meaning depends on the form:
//  LAYER_LIST: [0] front and [1] back fragments, kept running past the limits so the host can
//              grow the pool and repeat the pass; uFrontLimit / uBackLimit cap each side (both
//              the pool's size, unless the pool cannot grow: then they split it).
//  LAYER_FAB, LAYER_KB: [0] stored, [1] overflowed (the layer held more than K at the pixel).
// Needs surface.glsl (uObjectId) before it.
#include "layer_storage.glsl"
#include "oit/fragment_color.glsl"
#include "oit/subgroup_counter.glsl"

#if defined(LAYER_LIST)
layout(binding = BIND_COUNTERS, offset = 0) uniform atomic_uint uFrontCount;
layout(binding = BIND_COUNTERS, offset = 4) uniform atomic_uint uBackCount;
uniform uint uFrontLimit;
uniform uint uBackLimit;
#else
layout(binding = BIND_COUNTERS, offset = 0) uniform atomic_uint uStored;
layout(binding = BIND_COUNTERS, offset = 4) uniform atomic_uint uOverflowed;
#endif

// words: the fragment's colour words (oit/fragment_color.glsl: storedSurfaceColor()).
void storeLayerFragment(ivec2 pixel, int side, uvec2 words) {
#if defined(LAYER_LIST)
    uint index;
    if (side == 0) {
        index = subgroupCounterIncrement(uFrontCount);
        if (index >= uFrontLimit) return;
    } else {
        uint fromEnd = subgroupCounterIncrement(uBackCount);
        if (fromEnd >= uBackLimit) return;
        index = uCapacity - 1u - fromEnd;
    }
    uint head = imageAtomicExchange(uHeads, sidePixel(pixel, side), index + 1u);
    writeNode(index, gl_FragCoord.z, uObjectId, uint(gl_PrimitiveID), words, head);
#elif defined(LAYER_FAB)
    uint slot = imageAtomicAdd(uCounts, sidePixel(pixel, side), 1u);
    if (slot < uCapacity) {
        entries[firstEntry(pixel, side) + slot] = makeEntry(gl_FragCoord.z, uObjectId, uint(gl_PrimitiveID), words);
        subgroupCounterIncrement(uStored);
    } else {
        subgroupCounterIncrement(uOverflowed);
    }
#else
    // Claimed slots always form a prefix: a fragment tries slot i only after finding 0..i-1
    // claimed, and a claim is never released.
    uint first = firstEntry(pixel, side);
    for (uint i = 0u; i < uCapacity; ++i) {
        if (atomicCompSwap(entries[first + i].objectId, kUnclaimed, uObjectId) == kUnclaimed) {
            entries[first + i].depth = gl_FragCoord.z;
            entries[first + i].primitiveId = uint(gl_PrimitiveID);
            entries[first + i].colorRG = words.x;
            entries[first + i].colorBA = words.y;
            subgroupCounterIncrement(uStored);
            return;
        }
    }
    subgroupCounterIncrement(uOverflowed);
#endif
}
