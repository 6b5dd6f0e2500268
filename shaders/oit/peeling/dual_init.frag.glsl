#version 450 core
// Dual peeling initialisation: with MAX blending into RG32F, (z, -z) leaves the nearest depth in
// r and minus the farthest in g (reversed-Z: nearer is larger). The host counts the fragments
// in front of the opaque depth with a GL_SAMPLES_PASSED query (early depth test, no discard).

STRATA_EARLY_TESTS_NO_SIDE_EFFECTS  // common/scene_prelude.glsl
layout(location = 0) out vec2 outMinMax;

void main() {
    outMinMax = vec2(gl_FragCoord.z, -gl_FragCoord.z);
}
