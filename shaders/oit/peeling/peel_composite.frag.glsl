#version 450 core
// Final composite of front-to-back peeling: accumulated colour plus transmittance times the
// opaque colour.
#include "bindings.h"
#include "peel_bindings.h"

layout(binding = BIND_OPAQUE_COLOR) uniform sampler2D uOpaqueColor;
layout(binding = BIND_PEEL_ACCUM) uniform sampler2D uAccum;
layout(location = 0) out vec4 outColor;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec4 accum = texelFetch(uAccum, pixel, 0);
    outColor = vec4(accum.rgb + accum.a * texelFetch(uOpaqueColor, pixel, 0).rgb, 1.0);
}
