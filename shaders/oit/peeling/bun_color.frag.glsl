#version 450 core
// Bucket colour pass: a fragment whose depth is its bucket's nearest (farthest) captured depth
// stores its colour in the bucket's first (second) slot. Coincident fragments race for a slot.
// STRATA_RGB_TRANSMITTANCE: the slot holds the premultiplied colour, and the slot 2 uBuckets
// further on what the fragment lets through per channel; coincident fragments racing for one
// slot may then leave one's colour with the other's filter (bun is not coplanarity-aware).
#include "surface.glsl"
#include "bun_bucket.glsl"

layout(early_fragment_tests) in;
layout(binding = BIND_PEEL_LAYER) uniform sampler2DArray uBucketDepths;
// COLOR_FORMAT: rgba16f or rgba32f, the precision parameter's (the host defines it).
#ifndef COLOR_FORMAT
#define COLOR_FORMAT rgba16f
#endif
layout(binding = BIND_BUCKET_COLORS, COLOR_FORMAT) uniform writeonly image2DArray uColors;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float z = gl_FragCoord.z;
    int bucket = bucketOf(pixel, z);
    vec4 pair = texelFetch(uBucketDepths, ivec3(pixel, bucket / 2), 0);
    vec2 nearFar = (bucket % 2 == 0) ? pair.xy : pair.zw;
    int slot;
    if (z == nearFar.x)
        slot = 2 * bucket;
    else if (z == -nearFar.y)
        slot = 2 * bucket + 1;
    else
        return;
#ifdef STRATA_RGB_TRANSMITTANCE
    SurfaceOptics o = surfaceOptics();
    imageStore(uColors, ivec3(pixel, slot), vec4(o.premultiplied, 1.0));
    imageStore(uColors, ivec3(pixel, slot + 2 * uBuckets), vec4(o.transmittance, 1.0));
#else
    imageStore(uColors, ivec3(pixel, slot), surfaceColor());
#endif
}
