#version 450 core
// Dual peeling initialisation: with MAX blending into RG32F, (z, -z) leaves the nearest depth in
// r and minus the farthest in g (reversed-Z: nearer is larger). Counts every fragment in front
// of the opaque depth (the early depth test rejects the others before the count).
#include "bindings.glsl"

layout(early_fragment_tests) in;
layout(binding = BIND_COUNTERS, offset = 0) uniform atomic_uint uTotal;
layout(location = 0) out vec2 outMinMax;

void main() {
    atomicCounterIncrement(uTotal);
    outMinMax = vec2(gl_FragCoord.z, -gl_FragCoord.z);
}
