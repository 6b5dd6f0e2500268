#version 450 core
// dual-2p, after counting, one full-screen draw: per side (front, back) the pixels with one or
// more fragments counted and with two or more, tallied in two atomic counters with one atomic per
// subgroup (subgroup_counter.glsl), from which the host knows the fragments captured and whether
// to extract. A side with two or more has its colour targets (and opacity targets,
// STRATA_RGB_TRANSMITTANCE) zeroed here, for the extraction's MAX blending; a side with fewer
// keeps them: it holds its one fragment's colour, the counting pass's sum. One output zeroes or
// keeps every target through the host's blend, dst x (1 - src alpha) + 0, with src alpha 1 or 0.
// Pixels where neither side holds two are discarded after counting (the usual case: no
// coplanarity, no writes). It was four draws, one per side and threshold under occlusion
// queries: at 256x256 on llvmpipe a full-screen draw has a fixed part of about 0.2 ms.
#include "bindings.h"
#include "peel_bindings.h"
#include "oit/subgroup_counter.glsl"

layout(binding = BIND_COPLANAR_COUNT) uniform sampler2D uFrontCount;
layout(binding = BIND_COPLANAR_COUNT + BIND_COPLANAR_BACK_OFFSET) uniform sampler2D uBackCount;
layout(binding = BIND_COUNTERS, offset = 0) uniform atomic_uint uCoplanarSides;  // sides with two or more
layout(binding = BIND_COUNTERS, offset = 4) uniform atomic_uint uCountedSides;   // sides with one or more
layout(location = 0) out vec4 outFrontMin;
layout(location = 1) out vec4 outFrontMax;
layout(location = 2) out vec4 outBackMin;
layout(location = 3) out vec4 outBackMax;
#ifdef STRATA_RGB_TRANSMITTANCE
layout(location = 4) out vec4 outFrontMinOpacity;
layout(location = 5) out vec4 outFrontMaxOpacity;
layout(location = 6) out vec4 outBackMinOpacity;
layout(location = 7) out vec4 outBackMaxOpacity;
#endif

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float front = texelFetch(uFrontCount, pixel, 0).a;
    float back = texelFetch(uBackCount, pixel, 0).a;
    bool frontCoplanar = front > 1.5, backCoplanar = back > 1.5;
    subgroupCounterCount(uCoplanarSides, frontCoplanar);
    subgroupCounterCount(uCoplanarSides, backCoplanar);
    subgroupCounterCount(uCountedSides, front > 0.5);
    subgroupCounterCount(uCountedSides, back > 0.5);
    if (!frontCoplanar && !backCoplanar) discard;
    vec4 frontOut = vec4(0.0, 0.0, 0.0, frontCoplanar ? 1.0 : 0.0);
    vec4 backOut = vec4(0.0, 0.0, 0.0, backCoplanar ? 1.0 : 0.0);
    outFrontMin = frontOut;
    outFrontMax = frontOut;
    outBackMin = backOut;
    outBackMax = backOut;
#ifdef STRATA_RGB_TRANSMITTANCE
    outFrontMinOpacity = frontOut;
    outFrontMaxOpacity = frontOut;
    outBackMinOpacity = backOut;
    outBackMaxOpacity = backOut;
#endif
}
