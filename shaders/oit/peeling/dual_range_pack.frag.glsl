#version 450 core
// dual with atomic_range: turns the depth bits a peel pass left (dual_peel.frag.glsl) into the
// next range in the form the rest of dual reads, (nearest, -farthest) with (-2, -2) for an empty
// one, and resets the two texels for the pass after next. The images are ping-ponged like the
// ranges, so the barrier the host issues before the next pack (or at the next frame's start)
// orders this reset before the atomics that use these images again. With back_depth_test it
// also writes the back of the range to the depth buffer (dual_back_depth.glsl); without, no
// depth buffer is attached and the write goes nowhere.
#include "peel_bindings.h"
#include "dual_back_depth.glsl"

layout(binding = BIND_DUAL_NEXT_NEAREST, r32i) uniform iimage2D uNextNearest;
layout(binding = BIND_DUAL_NEXT_FARTHEST, r32i) uniform iimage2D uNextFarthest;

layout(location = 0) out vec2 outMinMax;

const int kNoNearest = -1;          // below every depth's bits
const int kNoFarthest = 0x7fffffff; // above them

void main() {
    const ivec2 pixel = ivec2(gl_FragCoord.xy);
    const int nearest = imageLoad(uNextNearest, pixel).r;
    const int farthest = imageLoad(uNextFarthest, pixel).r;
    imageStore(uNextNearest, pixel, ivec4(kNoNearest));
    imageStore(uNextFarthest, pixel, ivec4(kNoFarthest));
    // A fragment sets both or neither.
    outMinMax = nearest == kNoNearest ? vec2(-2.0) : vec2(intBitsToFloat(nearest), -intBitsToFloat(farthest));
    gl_FragDepth = dualBackDepth(outMinMax);
}
