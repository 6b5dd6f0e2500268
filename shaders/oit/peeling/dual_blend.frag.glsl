#version 450 core
// Dual peeling's per-pass full-screen steps, one draw each (uStep), so that occlusion queries
// count them with no atomics:
//  0: adds this pass's front layer under the front accumulation (front to back); a pixel
//     without a front layer is discarded, so GL_SAMPLES_PASSED counts the front layers;
//  1: adds the back layer over the back accumulation (back to front), counted the same way;
//  2: passes only where fragments are left strictly inside the next range (the peel wrote it;
//     -2 is the cleared, empty range): GL_ANY_SAMPLES_PASSED says whether to peel again. With
//     back_depth_test (and no atomic_range, whose pack does it) the host enables the depth test
//     (GL_ALWAYS, writes on) for this step alone, and a pixel that passes writes the back of
//     its next range, which the next peel tests against (dual_back_depth.glsl). A pixel whose
//     range is empty is discarded and keeps the host's clear value, 1, so the next peel shades
//     nothing there: most of what the test saves on a mesh, whose pixels finish at different
//     passes.
// The host sets the blend function and colour mask of each target per step.
// STRATA_RGB_TRANSMITTANCE (coloured filters): the layers hold premultiplied colours and their
// filters, and two more targets what each accumulation lets through per channel. Step 0 adds
// T x colour to the front accumulation (blend ONE, ONE) and multiplies T by the filter (ZERO,
// SRC_COLOR), reading T, its own texel; step 1 writes the back accumulation as colour + filter x
// what it held (no blending, reading its own texel) and multiplies the back T. Each pixel reads
// and writes its own texel once per draw, with texture barriers between the draws.
#include "peel_bindings.h"
#include "dual_back_depth.glsl"

layout(binding = BIND_PEEL_LAYER) uniform sampler2D uFront;
layout(binding = BIND_PEEL_BACK) uniform sampler2D uBack;
layout(binding = BIND_PEEL_PREVIOUS) uniform sampler2D uNextRange;
uniform int uStep;

layout(location = 0) out vec4 outFront;
layout(location = 1) out vec4 outBack;
#ifdef STRATA_RGB_TRANSMITTANCE
layout(binding = BIND_PEEL_LAYER_FILTER) uniform sampler2D uFrontFilter;
layout(binding = BIND_PEEL_BACK_FILTER) uniform sampler2D uBackFilter;
layout(binding = BIND_PEEL_ACCUM_FILTER) uniform sampler2D uFrontAccumFilter;
layout(binding = BIND_PEEL_BACK_ACCUM) uniform sampler2D uBackAccum;
layout(location = 2) out vec4 outFrontAccumFilter;
layout(location = 3) out vec4 outBackAccumFilter;
#endif

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    gl_FragDepth = 0.0;  // written only in step 2, the others run without the depth test
    outFront = vec4(0.0);  // neutral under both blend functions
    outBack = vec4(0.0);
#ifdef STRATA_RGB_TRANSMITTANCE
    outFrontAccumFilter = vec4(1.0);
    outBackAccumFilter = vec4(1.0);
    if (uStep == 0) {
        vec4 f = texelFetch(uFront, pixel, 0);
        if (f.a < 1.0) discard;
        outFront = vec4(texelFetch(uFrontAccumFilter, pixel, 0).rgb * f.rgb, 0.0);
        outFrontAccumFilter = vec4(texelFetch(uFrontFilter, pixel, 0).rgb, 1.0);
        return;
    }
    if (uStep == 1) {
        vec4 b = texelFetch(uBack, pixel, 0);
        if (b.a < 1.0) discard;
        vec3 filterOfLayer = texelFetch(uBackFilter, pixel, 0).rgb;
        outBack = vec4(b.rgb + filterOfLayer * texelFetch(uBackAccum, pixel, 0).rgb, 1.0);
        outBackAccumFilter = vec4(filterOfLayer, 1.0);
        return;
    }
#endif
    if (uStep == 0) {
        vec4 f = texelFetch(uFront, pixel, 0);
        if (f.a < 1.0) discard;
        float a = f.a - 1.0;
        outFront = vec4(f.rgb * a, a);
    } else if (uStep == 1) {
        vec4 b = texelFetch(uBack, pixel, 0);
        if (b.a < 1.0) discard;
        outBack = vec4(b.rgb, b.a - 1.0);
    } else {
        vec2 next = texelFetch(uNextRange, pixel, 0).rg;
        if (next.r <= -1.5) discard;
        gl_FragDepth = dualBackDepth(next);
    }
}
