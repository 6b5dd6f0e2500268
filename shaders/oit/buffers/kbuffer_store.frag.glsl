#version 450 core
// K-buffer without fragment-shader interlock (llvmpipe has none), in two geometry passes of the
// same program so both rasterize identical depths:
//  pass 0: lock-free insertion of the fragment's depth key into the pixel's K slots, kept sorted
//          nearest first, with a chain of 32-bit atomicMax: the key goes into slot 0, whatever
//          it displaces (the smaller of the two) moves on to slot 1, and so on. Every step is
//          one atomic, so nothing can spin or hang; after all fragments the slots hold the K
//          largest (reversed-Z: nearest) depths. A key pushed past slot K-1 is counted dropped.
//  pass 1: each fragment looks its depth up among the K keys and claims one slot of that depth
//          with atomicCompSwap on the slot's object id, then writes its attributes. Coincident
//          fragments (equal depth) claim the equal-key slots one each; the resolve sorts them by
//          (object id, primitive id). A fragment whose depth is not kept (or that finds every
//          equal-key slot claimed) goes to the tail when it is on.
// Depth keys: floatBitsToUint of a depth in (0, 1] orders like the float; 0 marks an empty slot
// (a transparent fragment passing GL_GREATER against the opaque depth has depth > 0).
#include "surface.glsl"
#include "entry.glsl"
#include "oit/fragment_color.glsl"
#include "tail_store.glsl"
#include "oit/subgroup_counter.glsl"

layout(early_fragment_tests) in;
layout(std430, binding = BIND_DEPTH_KEYS) coherent buffer DepthKeys { uint depthKeys[]; };
layout(binding = BIND_COUNTERS, offset = 0) uniform atomic_uint uInserted;
layout(binding = BIND_COUNTERS, offset = 4) uniform atomic_uint uDropped;
uniform uint uWidth;
uniform uint uCapacity;
uniform int uPass;

const uint kUnclaimed = 0xFFFFFFFFu;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    uint first = (uint(pixel.y) * uWidth + uint(pixel.x)) * uCapacity;
    uint key = floatBitsToUint(gl_FragCoord.z);
    if (uPass == 0) {
        subgroupCounterIncrement(uInserted);
        uint carried = key;
        for (uint i = 0u; i < uCapacity; ++i) {
            uint previous = atomicMax(depthKeys[first + i], carried);
            if (previous == 0u) { carried = 0u; break; }  // took an empty slot
            carried = min(previous, carried);             // the displaced (or refused) key moves on
        }
        if (carried != 0u) subgroupCounterIncrement(uDropped);
        return;
    }
    StoredColor fragmentColor = storedSurfaceColor();
    vec4 c = fragmentColor.scalar;
    uvec2 words = fragmentColor.words;
    bool stored = false;
    for (uint i = 0u; i < uCapacity && !stored; ++i) {
        uint k = depthKeys[first + i];
        if (k < key) break;  // sorted nearest first: no equal key further on
        if (k != key) continue;
        if (atomicCompSwap(entries[first + i].objectId, kUnclaimed, uObjectId) == kUnclaimed) {
            entries[first + i].depth = gl_FragCoord.z;
            entries[first + i].primitiveId = uint(gl_PrimitiveID);
            entries[first + i].colorRG = words.x;
            entries[first + i].colorBA = words.y;
            stored = true;
        }
    }
    if (stored) tailNone(); else tailAdd(c);
}
