#version 450 core
// Per-pixel linked lists with a FIXED node pool (Yang et al.; the A-buffer's node layout): one
// global atomic counter hands out nodes, the heads image links them. Unlike abuffer the pool
// does not grow: fragments past its end are counted (the counter keeps running) and dropped or,
// with the tail on, blended approximately.
#include "surface.glsl"
#include "oit/abuffer_storage.glsl"
#include "oit/fragment_color.glsl"
#include "oit/subgroup_counter.glsl"
#include "buffer_bindings.h"
#include "tail_store.glsl"

#ifdef VOLUME
#include "oit/volume/volume_store.glsl"
#endif

layout(early_fragment_tests) in;
layout(binding = BIND_COUNTERS, offset = 0) uniform atomic_uint uNodeCount;
uniform uint uCapacity;  // nodes in the pool

void main() {
    StoredColor fragmentColor = storedSurfaceColor();
    vec4 c = fragmentColor.scalar;
    uvec2 words = fragmentColor.words;
    uint index = subgroupCounterIncrement(uNodeCount);
    if (index >= uCapacity) { tailAdd(c); return; }
#ifdef VOLUME
    uint primitiveBits = uint(gl_PrimitiveID) | volumeFlags();
#else
    uint primitiveBits = uint(gl_PrimitiveID);
#endif
    uint head = imageAtomicExchange(uHeads, ivec2(gl_FragCoord.xy), index + 1u);
    writeNode(index, gl_FragCoord.z, uObjectId, primitiveBits, words, head);
    tailNone();
}
