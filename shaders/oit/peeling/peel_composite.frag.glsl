#version 450 core
// Final composite of depth peeling: the front accumulation (premultiplied colour, transmittance),
// then with DUAL the back accumulation behind it, then the opaque colour.
#include "bindings.h"
#include "peel_bindings.h"

layout(binding = BIND_OPAQUE_COLOR) uniform sampler2D uOpaqueColor;
layout(binding = BIND_PEEL_ACCUM) uniform sampler2D uAccum;
#ifdef DUAL
layout(binding = BIND_PEEL_BACK_ACCUM) uniform sampler2D uBackAccum;
#endif
#ifdef STRATA_RGB_TRANSMITTANCE
layout(binding = BIND_PEEL_ACCUM_FILTER) uniform sampler2D uAccumFilter;  // T per channel
#ifdef DUAL
layout(binding = BIND_PEEL_BACK_ACCUM_FILTER) uniform sampler2D uBackAccumFilter;
#endif
#endif
layout(location = 0) out vec4 outColor;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec4 front = texelFetch(uAccum, pixel, 0);
    vec3 behind = texelFetch(uOpaqueColor, pixel, 0).rgb;
#ifdef DUAL
    vec4 back = texelFetch(uBackAccum, pixel, 0);
#ifdef STRATA_RGB_TRANSMITTANCE
    behind = back.rgb + texelFetch(uBackAccumFilter, pixel, 0).rgb * behind;
#else
    behind = back.rgb + back.a * behind;
#endif
#endif
#ifdef STRATA_RGB_TRANSMITTANCE
    outColor = vec4(front.rgb + texelFetch(uAccumFilter, pixel, 0).rgb * behind, 1.0);
#else
    outColor = vec4(front.rgb + front.a * behind, 1.0);
#endif
}
