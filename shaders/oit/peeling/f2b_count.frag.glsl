#version 450 core
// f2b and f2b2's fragment count (and dual's with atomic_range), before the first peel: drawn
// against the opaque depth (no
// writes) with colour writes off, under a GL_SAMPLES_PASSED query. The host peels down to that
// total. Counting in the first peel instead (an atomic per fragment) made that peel's depth
// test late, so every fragment behind the nearest one drawn so far was shaded: 45 % of f2b's
// frame at 256x256 with 8 layers on llvmpipe. Here the test runs early and nothing is shaded.

STRATA_EARLY_TESTS_NO_SIDE_EFFECTS  // common/scene_prelude.glsl

void main() {}
