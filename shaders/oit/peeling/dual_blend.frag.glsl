#version 450 core
// Dual peeling's per-pass full-screen blend, one draw for what used to take three:
//  - adds this pass's front layer under the front accumulation (front to back);
//  - adds the back layer over the back accumulation (back to front);
//  - counts both layers and the pixels with fragments left strictly inside the next range (the
//    peel wrote it; -2 is the cleared, empty range) in three atomic counters, one atomic per
//    subgroup (subgroup_counter.glsl): the host reads them per pass, to know how many fragments
//    the pass took and whether to peel again. Occlusion queries would need a draw per count, and
//    a full-screen draw cost 0.3 ms at 256x256 on llvmpipe (results.md).
// A pixel without a front (back) layer writes the blend's neutral value, so every pixel runs
// once and none is discarded. With back_depth_test (and no atomic_range, whose pack does it) the
// host attaches the next peel's depth buffer with the depth test GL_ALWAYS and writes on: every
// pixel of the transparent area (the host's scissor; no peel draws outside it) writes the back
// of its next range, or 1 (the near plane) where the range is empty, so
// the next peel shades nothing there (dual_back_depth.glsl): most of what the test saves on a
// mesh, whose pixels finish at different passes.
// STRATA_RGB_TRANSMITTANCE (coloured filters): the layers hold premultiplied colours and their
// filters, and two more targets what each accumulation lets through per channel. The front adds
// T x colour to the front accumulation (blend ONE, ONE) and multiplies T by the filter (ZERO,
// SRC_COLOR), reading T, its own texel; the back writes the back accumulation as colour + filter
// x what it held (no blending, reading its own texel; unchanged without a back layer) and
// multiplies the back T. Each pixel reads and writes its own texels once, after a texture barrier.
#include "bindings.h"
#include "peel_bindings.h"
#include "dual_back_depth.glsl"
#include "oit/subgroup_counter.glsl"

layout(binding = BIND_PEEL_LAYER) uniform sampler2D uFront;
layout(binding = BIND_PEEL_BACK) uniform sampler2D uBack;
layout(binding = BIND_PEEL_PREVIOUS) uniform sampler2D uNextRange;
layout(binding = BIND_COUNTERS, offset = 0) uniform atomic_uint uFrontLayers;
layout(binding = BIND_COUNTERS, offset = 4) uniform atomic_uint uBackLayers;
layout(binding = BIND_COUNTERS, offset = 8) uniform atomic_uint uInteriorLeft;

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
    vec4 f = texelFetch(uFront, pixel, 0);
    vec4 b = texelFetch(uBack, pixel, 0);
    vec2 next = texelFetch(uNextRange, pixel, 0).rg;
    // A layer's alpha is stored plus 1, so 0 (the clear) means none.
    bool hasFront = f.a >= 1.0;
    bool hasBack = b.a >= 1.0;
    subgroupCounterCount(uFrontLayers, hasFront);
    subgroupCounterCount(uBackLayers, hasBack);
    subgroupCounterCount(uInteriorLeft, next.r > -1.5);
    gl_FragDepth = dualBackDepth(next);  // 1 for an empty range; kept only where depth is attached
#ifdef STRATA_RGB_TRANSMITTANCE
    outFront = vec4(0.0);               // neutral under ONE, ONE
    outFrontAccumFilter = vec4(1.0);    // and under ZERO, SRC_COLOR
    outBackAccumFilter = vec4(1.0);
    outBack = texelFetch(uBackAccum, pixel, 0);  // unblended: rewritten as it was
    if (hasFront) {
        outFront = vec4(texelFetch(uFrontAccumFilter, pixel, 0).rgb * f.rgb, 0.0);
        outFrontAccumFilter = vec4(texelFetch(uFrontFilter, pixel, 0).rgb, 1.0);
    }
    if (hasBack) {
        vec3 filterOfLayer = texelFetch(uBackFilter, pixel, 0).rgb;
        outBack = vec4(b.rgb + filterOfLayer * outBack.rgb, 1.0);
        outBackAccumFilter = vec4(filterOfLayer, 1.0);
    }
#else
    // 0 is neutral under both blend functions.
    float a = f.a - 1.0;
    outFront = hasFront ? vec4(f.rgb * a, a) : vec4(0.0);
    outBack = hasBack ? vec4(b.rgb, b.a - 1.0) : vec4(0.0);
#endif
}
