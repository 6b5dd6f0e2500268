#version 450 core
// Coplanarity-aware peeling, initialisation: the first layers' anchors. The front state is
// cleared to -1 and MAX-blended (the nearest depth), dual-2p's back state cleared to 2 and
// MIN-blended (the farthest); the host masks the id channels, so they keep their cleared, open
// ranges. GL_SAMPLES_PASSED (early tests, no discard) counts every fragment in front of the
// opaque depth: the total that peeling runs down to.
STRATA_EARLY_TESTS_NO_SIDE_EFFECTS  // common/scene_prelude.glsl
layout(location = 0) out vec4 outFront;
layout(location = 1) out vec4 outBack;

void main() {
    outFront = vec4(gl_FragCoord.z);
    outBack = vec4(gl_FragCoord.z);
}
