#version 450 core
// Dual peeling composite: front accumulation (colour, transmittance), then the back
// accumulation (colour, transmittance), then the opaque colour.
#include "bindings.h"
#include "peel_bindings.h"

layout(binding = BIND_OPAQUE_COLOR) uniform sampler2D uOpaqueColor;
layout(binding = BIND_PEEL_ACCUM) uniform sampler2D uFrontAccum;
layout(binding = BIND_PEEL_BACK_ACCUM) uniform sampler2D uBackAccum;
layout(location = 0) out vec4 outColor;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec4 front = texelFetch(uFrontAccum, pixel, 0);
    vec4 back = texelFetch(uBackAccum, pixel, 0);
    vec3 behind = back.rgb + back.a * texelFetch(uOpaqueColor, pixel, 0).rgb;
    outColor = vec4(front.rgb + front.a * behind, 1.0);
}
