#version 450 core
// Weighted blended OIT composite: the weighted average colour covers (1 - revealage) of the
// pixel, the opaque colour shows through the rest. Clamps as in the paper (alpha sum in
// [1e-4, 5e4], times the accumulation's weight scale) keep the division finite.
#include "bindings.h"
#include "approximate_bindings.h"

layout(binding = BIND_OPAQUE_COLOR) uniform sampler2D uOpaqueColor;
layout(binding = BIND_ACCUM) uniform sampler2D uAccum;
layout(binding = BIND_TRANSMITTANCE) uniform sampler2D uRevealage;

uniform float uWeightScale = 1.0;

layout(location = 0) out vec4 outColor;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec3 opaque = texelFetch(uOpaqueColor, pixel, 0).rgb;
    vec4 accum = texelFetch(uAccum, pixel, 0);
    float revealage = texelFetch(uRevealage, pixel, 0).r;
    vec3 average = accum.rgb / clamp(accum.a, 1e-4 * uWeightScale, 5e4 * uWeightScale);
    outColor = vec4(average * (1.0 - revealage) + revealage * opaque, 1.0);
}
