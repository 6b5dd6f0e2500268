#version 450 core
// Dual peeling initialisation: with MAX blending into RG32F, (z, -z) leaves the nearest depth in
// r and minus the farthest in g (reversed-Z: nearer is larger). The host counts the fragments
// in front of the opaque depth with a GL_SAMPLES_PASSED query (early depth test, no discard).
//
// STRATA_DUAL_ATOMIC_RANGE (atomic_range): the same extremes by image atomics on the depth bits
// (dual_peel.frag.glsl), every fragment then discarded, so none reaches the blending units;
// dual_range_pack.frag.glsl writes the range. The count then comes from a pass of its own
// (f2b_count.frag.glsl): under the early tests the atomics need, a query would also count the
// texels a wrapped variant's alpha test discards.
#include "peel_bindings.h"

#ifdef STRATA_DUAL_ATOMIC_RANGE
#include "dual_range_images.glsl"
layout(early_fragment_tests) in;  // the opaque depth test before the atomics

void main() {
    addToNextRange(gl_FragCoord.z);
    discard;
}
#else
STRATA_EARLY_TESTS_NO_SIDE_EFFECTS  // common/scene_prelude.glsl
layout(location = 0) out vec2 outMinMax;

void main() {
    outMinMax = vec2(gl_FragCoord.z, -gl_FragCoord.z);
}
#endif
