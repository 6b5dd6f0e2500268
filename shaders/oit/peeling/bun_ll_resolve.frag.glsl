#version 450 core
// BUN-LL resolve: the pixel's bucket lists, nearest bucket first, composite over the opaque
// colour in the exact order of ordered_composite.glsl. The sequence it sorts runs bucket by
// bucket, and every fragment of a bucket is farther than every fragment of the buckets before
// it, so the insertion sort moves a fragment only past fragments of its own bucket: it is the
// paper's per-bucket post-sort. Because the sort and the tie rule see the whole sequence, surfaces
// that coincide up to round-off still form one layer where a bucket boundary falls between them.
#define HEADS_ARRAY
#include "bindings.h"
#include "oit/abuffer_storage.glsl"
#include "oit/packed_color.glsl"

#ifndef MAX_BUCKETS
#define MAX_BUCKETS 32
#endif

layout(binding = BIND_OPAQUE_COLOR) uniform sampler2D uOpaqueColor;
uniform int uBuckets;
layout(location = 0) out vec4 outColor;

uint gHeads[MAX_BUCKETS];  // the pixel's list heads as node indices, 0xFFFFFFFF for empty

float fragmentDepth(uint i) { return nodes[i].depth; }
uint fragmentObject(uint i) { return nodes[i].objectId; }
uint fragmentPrimitive(uint i) { return nodes[i].primitiveId; }
void compositeFragment(uint i, inout vec3 color, inout Transmittance transmittance) {
    compositePacked(nodes[i].colorRG, nodes[i].colorBA, color, transmittance);
}

// Every fragment, bucket by bucket (a `break` in the body leaves one bucket's list only; the
// callers' breaks stop on a condition that then holds for the next bucket's first step too).
#define FOR_EACH_FRAGMENT(i) \
    for (int bucket_ = 0; bucket_ < uBuckets; ++bucket_) \
        for (uint i = gHeads[bucket_]; i != 0xFFFFFFFFu; i = nodes[i].next - 1u)
#include "oit/ordered_composite.glsl"

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    for (int b = 0; b < uBuckets; ++b) gHeads[b] = imageLoad(uHeads, ivec3(pixel, b)).r - 1u;
    vec3 color = vec3(0.0);
    Transmittance transmittance = Transmittance(1.0);
    compositeInDepthOrder(color, transmittance);
    outColor = vec4(color + transmittance * texelFetch(uOpaqueColor, pixel, 0).rgb, 1.0);
}
