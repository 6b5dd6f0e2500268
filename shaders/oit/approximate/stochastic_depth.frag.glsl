#version 450 core
// Stochastic transparency, pass 1: the stochastic depth of each sample is the nearest
// fragment whose random mask covers it (atomicMax on reversed-Z depth bits). Early fragment
// tests keep fragments behind the opaque depth from touching the image.
#include "stochastic_common.glsl"

layout(early_fragment_tests) in;
layout(binding = BIND_SAMPLE_DEPTHS, r32ui) uniform coherent uimage2DArray uSampleDepths;

void main() {
    float alpha = surfaceColor().a;
    uint seed = fragmentSeed();
    uint bits = depthBits();
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    for (int s = 0; s < uSamples; ++s)
        if (coversSample(seed, s, alpha)) imageAtomicMax(uSampleDepths, ivec3(pixel, s), bits);
}
