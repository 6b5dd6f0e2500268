#version 450 core
// Bucket composite: buckets near to far, each bucket's nearest then (when distinct) farthest
// fragment, over the opaque colour. Counts the fragments composited. STRATA_RGB_TRANSMITTANCE:
// the slots hold premultiplied colours, and the slots 2 uBuckets on their filters.
#include "bindings.h"
#include "peel_bindings.h"
#include "oit/transmittance.glsl"
#include "oit/subgroup_counter.glsl"

layout(binding = BIND_OPAQUE_COLOR) uniform sampler2D uOpaqueColor;
layout(binding = BIND_PEEL_LAYER) uniform sampler2DArray uBucketDepths;
layout(binding = BIND_PEEL_ACCUM) uniform sampler2DArray uColors;
layout(binding = BIND_COUNTERS, offset = 4) uniform atomic_uint uCaptured;
uniform int uBuckets;
layout(location = 0) out vec4 outColor;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec3 color = vec3(0.0);
    Transmittance transmittance = Transmittance(1.0);
    for (int b = 0; b < uBuckets; ++b) {
        vec4 pair = texelFetch(uBucketDepths, ivec3(pixel, b / 2), 0);
        vec2 nearFar = (b % 2 == 0) ? pair.xy : pair.zw;
        if (nearFar.x <= 0.0) continue;  // empty bucket (cleared to -2)
        int count = (-nearFar.y != nearFar.x) ? 2 : 1;
        for (int i = 0; i < count; ++i) {
            vec4 c = texelFetch(uColors, ivec3(pixel, 2 * b + i), 0);
#ifdef STRATA_RGB_TRANSMITTANCE
            color += transmittance * c.rgb;
            transmittance *= texelFetch(uColors, ivec3(pixel, 2 * uBuckets + 2 * b + i), 0).rgb;
#else
            color += transmittance * c.a * c.rgb;
            transmittance *= 1.0 - c.a;
#endif
            subgroupCounterIncrement(uCaptured);
        }
    }
    outColor = vec4(color + transmittance * texelFetch(uOpaqueColor, pixel, 0).rgb, 1.0);
}
