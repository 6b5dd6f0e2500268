#version 450 core
// Adds this pass's front layer under the front accumulation (front to back) and its back layer
// over the back accumulation (back to front); the host sets the two blend functions per target.
// Counts the layers present: the fragments captured.
#include "bindings.glsl"
#include "peel_bindings.glsl"

layout(binding = BIND_PEEL_LAYER) uniform sampler2D uFront;
layout(binding = BIND_PEEL_BACK) uniform sampler2D uBack;
layout(binding = BIND_COUNTERS, offset = 8) uniform atomic_uint uCaptured;

layout(location = 0) out vec4 outFront;
layout(location = 1) out vec4 outBack;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec4 f = texelFetch(uFront, pixel, 0);
    vec4 b = texelFetch(uBack, pixel, 0);
    outFront = vec4(0.0);  // neutral under both blend functions
    outBack = vec4(0.0);
    if (f.a >= 1.0) {
        float a = f.a - 1.0;
        outFront = vec4(f.rgb * a, a);
        atomicCounterIncrement(uCaptured);
    }
    if (b.a >= 1.0) {
        outBack = vec4(b.rgb, b.a - 1.0);
        atomicCounterIncrement(uCaptured);
    }
}
