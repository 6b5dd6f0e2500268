#version 450 core
// Bucket capture (Liu et al. 2009): each fragment writes (z, -z) into its bucket's pair of
// channels with MAX blending, so each bucket keeps its nearest and farthest depth; two buckets
// per RGBA32F target, up to MAX_TARGETS targets. Every other channel gets -2, the neutral value
// the targets are cleared to. Two fragments per bucket survive; the rest collide and are lost.
#include "bun_bucket.glsl"
#include "oit/subgroup_counter.glsl"

#ifndef MAX_TARGETS
#define MAX_TARGETS 8
#endif

layout(early_fragment_tests) in;
layout(binding = BIND_COUNTERS, offset = 0) uniform atomic_uint uTotal;
layout(location = 0) out vec4 outBuckets[MAX_TARGETS];

void main() {
    subgroupCounterIncrement(uTotal);
    float z = gl_FragCoord.z;
    int bucket = bucketOf(ivec2(gl_FragCoord.xy), z);
    int target = bucket / 2;
    vec4 value = (bucket % 2 == 0) ? vec4(z, -z, -2.0, -2.0) : vec4(-2.0, -2.0, z, -z);
    for (int i = 0; i < MAX_TARGETS; ++i) outBuckets[i] = (i == target) ? value : vec4(-2.0);
}
