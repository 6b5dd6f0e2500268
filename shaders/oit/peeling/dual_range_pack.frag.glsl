#version 450 core
// dual with atomic_range: turns the depth bits a peel pass left (dual_peel.frag.glsl) into the
// next range in the form the rest of dual reads, (nearest, -farthest) with (-2, -2) for an empty
// one, and resets the two texels for the pass after next. The images are ping-ponged like the
// ranges, so the barrier the host issues before the next pack (or at the next frame's start)
// orders this reset before the atomics that use these images again. With back_depth_test it
// also writes the back of the range to the depth buffer (dual_back_depth.glsl); without, no
// depth buffer is attached and the write goes nowhere.
#include "dual_back_depth.glsl"
#include "dual_range_images.glsl"

layout(location = 0) out vec2 outMinMax;

void main() {
    const ivec2 pixel = ivec2(gl_FragCoord.xy);
    const int nearest = imageLoad(uNextNearest, pixel).r;
    const int farthest = imageLoad(uNextFarthest, pixel).r;
    imageStore(uNextNearest, pixel, ivec4(DUAL_NO_NEAREST));
    imageStore(uNextFarthest, pixel, ivec4(DUAL_NO_FARTHEST));
    // A fragment sets both or neither.
    outMinMax = nearest == DUAL_NO_NEAREST ? vec2(-2.0) : vec2(intBitsToFloat(nearest), -intBitsToFloat(farthest));
    gl_FragDepth = dualBackDepth(outMinMax);
}
