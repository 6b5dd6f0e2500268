#version 450 core
// A-buffer store pass: every transparent fragment in front of the opaque depth is appended to
// its pixel's list. Fragments past the pool's capacity are counted (the counter keeps running)
// but not stored; the host grows the pool to the counted size and renders again.
#include "surface.glsl"
#include "abuffer_storage.glsl"
#include "fragment_color.glsl"
#include "oit/subgroup_counter.glsl"

#ifdef VOLUME
#include "oit/volume/volume_store.glsl"
#endif

layout(early_fragment_tests) in;
layout(binding = BIND_COUNTERS, offset = 0) uniform atomic_uint uNodeCount;
uniform uint uCapacity;

void main() {
    // The colour first: its texture fetches need derivatives, which a fragment that has left
    // by the branch below no longer helps compute (oit/fragment_color.glsl).
    uvec2 words = storedSurfaceColor().words;
    uint index = subgroupCounterIncrement(uNodeCount);
    if (index >= uCapacity) return;
#ifdef VOLUME
    uint primitiveBits = uint(gl_PrimitiveID) | volumeFlags();
#else
    uint primitiveBits = uint(gl_PrimitiveID);
#endif
    uint head = imageAtomicExchange(uHeads, ivec2(gl_FragCoord.xy), index + 1u);
    writeNode(index, gl_FragCoord.z, uObjectId, primitiveBits, words, head);
}
