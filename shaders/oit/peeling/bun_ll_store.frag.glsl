#version 450 core
// BUN-LL store pass (depth-fighting paper, section 3.1.4): every transparent fragment in front
// of the opaque depth goes into the linked list of its depth bucket (bun_bucket.glsl: the
// pixel's range split into uniform intervals of eye distance), one head per pixel and bucket.
// One node pool and one counter for all buckets, grown by the host to the fragments counted
// (the counter keeps running past the pool; core/oit/fragment_lists.hpp), so nothing overflows.
#define HEADS_ARRAY
#include "surface.glsl"
#include "bun_bucket.glsl"
#include "oit/abuffer_storage.glsl"
#include "oit/fragment_color.glsl"
#include "oit/subgroup_counter.glsl"

layout(early_fragment_tests) in;
layout(binding = BIND_COUNTERS, offset = 0) uniform atomic_uint uNodeCount;
uniform uint uCapacity;

void main() {
    uvec2 words = storedSurfaceColor().words;  // before the branch: oit/fragment_color.glsl
    uint index = subgroupCounterIncrement(uNodeCount);
    if (index >= uCapacity) return;
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    uint head = imageAtomicExchange(uHeads, ivec3(pixel, bucketOf(pixel, gl_FragCoord.z)), index + 1u);
    writeNode(index, gl_FragCoord.z, uObjectId, uint(gl_PrimitiveID), words, head);
}
