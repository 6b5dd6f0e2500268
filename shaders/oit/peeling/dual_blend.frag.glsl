#version 450 core
// Dual peeling's per-pass full-screen steps, one draw each (uStep), so that occlusion queries
// count them with no atomics:
//  0: adds this pass's front layer under the front accumulation (front to back); a pixel
//     without a front layer is discarded, so GL_SAMPLES_PASSED counts the front layers;
//  1: adds the back layer over the back accumulation (back to front), counted the same way;
//  2: passes only where fragments are left strictly inside the next range (the peel wrote it;
//     -2 is the cleared, empty range): GL_ANY_SAMPLES_PASSED says whether to peel again.
// The host sets the blend function and colour mask of each target per step.
#include "peel_bindings.h"

layout(binding = BIND_PEEL_LAYER) uniform sampler2D uFront;
layout(binding = BIND_PEEL_BACK) uniform sampler2D uBack;
layout(binding = BIND_PEEL_PREVIOUS) uniform sampler2D uNextRange;
uniform int uStep;

layout(location = 0) out vec4 outFront;
layout(location = 1) out vec4 outBack;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    outFront = vec4(0.0);  // neutral under both blend functions
    outBack = vec4(0.0);
    if (uStep == 0) {
        vec4 f = texelFetch(uFront, pixel, 0);
        if (f.a < 1.0) discard;
        float a = f.a - 1.0;
        outFront = vec4(f.rgb * a, a);
    } else if (uStep == 1) {
        vec4 b = texelFetch(uBack, pixel, 0);
        if (b.a < 1.0) discard;
        outBack = vec4(b.rgb, b.a - 1.0);
    } else if (texelFetch(uNextRange, pixel, 0).r <= -1.5) {
        discard;
    }
}
