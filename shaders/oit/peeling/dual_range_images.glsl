// dual with atomic_range: the two r32i images where a pass leaves the next range, as the depth
// bits of its nearest (max) and farthest (min) fragment. Depths are >= 0, so their bits order
// as the floats do; abs() makes a -0 the +0 it equals (its bits would order below every depth).
// Empty: DUAL_NO_NEAREST and DUAL_NO_FARTHEST (peel_bindings.h), which the host clears to and
// dual_range_pack.frag.glsl resets to.
#ifndef STRATA_DUAL_RANGE_IMAGES_GLSL
#define STRATA_DUAL_RANGE_IMAGES_GLSL
#include "peel_bindings.h"

layout(binding = BIND_DUAL_NEXT_NEAREST, r32i) uniform iimage2D uNextNearest;
layout(binding = BIND_DUAL_NEXT_FARTHEST, r32i) uniform iimage2D uNextFarthest;

// This fragment's depth into its pixel's next range.
void addToNextRange(float z) {
    const int bits = floatBitsToInt(abs(z));
    imageAtomicMax(uNextNearest, ivec2(gl_FragCoord.xy), bits);
    imageAtomicMin(uNextFarthest, ivec2(gl_FragCoord.xy), bits);
}
#endif
