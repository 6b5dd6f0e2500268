#version 450 core
// Stochastic transparency composite with the paper's alpha correction: the accumulated colour
// is rescaled so the transparent layers cover exactly (1 - T_total), where T_total is the exact
// product of (1 - alpha) from the multiplicative target; the opaque colour shows through T_total.
#include "bindings.h"
#include "approximate_bindings.h"

layout(binding = BIND_OPAQUE_COLOR) uniform sampler2D uOpaqueColor;
layout(binding = BIND_ACCUM) uniform sampler2D uAccum;
layout(binding = BIND_TRANSMITTANCE) uniform sampler2D uTransmittance;

layout(location = 0) out vec4 outColor;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec3 opaque = texelFetch(uOpaqueColor, pixel, 0).rgb;
    vec4 accum = texelFetch(uAccum, pixel, 0);
    float transmittance = texelFetch(uTransmittance, pixel, 0).r;
    vec3 color = accum.a > 0.0 ? accum.rgb * ((1.0 - transmittance) / accum.a) : vec3(0.0);
    outColor = vec4(color + transmittance * opaque, 1.0);
}
