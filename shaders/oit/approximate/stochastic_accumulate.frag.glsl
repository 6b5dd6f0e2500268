#version 450 core
// Stochastic transparency, pass 2: a fragment's visibility is the share of samples whose
// stochastic depth is not nearer than it (an unbiased estimate of the product of (1 - alpha)
// over the fragments in front). Location 0 adds (alpha * colour * vis, alpha * vis); location 1
// multiplies the exact total transmittance, T *= (1 - alpha), blended (ZERO, ONE_MINUS_SRC_COLOR).
#include "stochastic_common.glsl"

STRATA_EARLY_TESTS_NO_SIDE_EFFECTS  // common/scene_prelude.glsl
layout(binding = BIND_SAMPLE_DEPTHS, r32ui) uniform readonly uimage2DArray uSampleDepths;

layout(location = 0) out vec4 outAccum;
layout(location = 1) out vec4 outTransmittance;

void main() {
    vec4 c = surfaceColor();
    uint bits = depthBits();
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    int visible = 0;
    for (int s = 0; s < uSamples; ++s)
        if (bits >= imageLoad(uSampleDepths, ivec3(pixel, s)).r) ++visible;
    float vis = float(visible) / float(uSamples);
    outAccum = vec4(c.rgb * c.a * vis, c.a * vis);
    outTransmittance = vec4(c.a);
}
