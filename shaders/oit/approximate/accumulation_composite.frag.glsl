#version 450 core
// Composite of the accumulation techniques: an additive colour-and-alpha sum and a product of
// (1 - alpha) (transmittance), over the opaque colour. The two differ only in how the sum
// becomes the colour that covers (1 - transmittance) of the pixel:
//   WEIGHTED_AVERAGE (wboit): the depth-weighted average, sum.rgb / sum.a, with the paper's clamp
//     of the alpha sum to [1e-4, 5e4] (times the accumulation's weight scale) so the division
//     stays finite;
//   ALPHA_CORRECTED (stochastic): the sum rescaled so it covers exactly (1 - transmittance), the
//     paper's alpha correction.
#include "bindings.h"
#include "approximate_bindings.h"

layout(binding = BIND_OPAQUE_COLOR) uniform sampler2D uOpaqueColor;
layout(binding = BIND_ACCUM) uniform sampler2D uAccum;
layout(binding = BIND_TRANSMITTANCE) uniform sampler2D uTransmittance;

#if defined(WEIGHTED_AVERAGE)
uniform float uWeightScale = 1.0;
#elif !defined(ALPHA_CORRECTED)
#error "define WEIGHTED_AVERAGE or ALPHA_CORRECTED"
#endif

layout(location = 0) out vec4 outColor;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec3 opaque = texelFetch(uOpaqueColor, pixel, 0).rgb;
    vec4 accum = texelFetch(uAccum, pixel, 0);
    float transmittance = texelFetch(uTransmittance, pixel, 0).r;
#if defined(WEIGHTED_AVERAGE)
    vec3 color = accum.rgb / clamp(accum.a, 1e-4 * uWeightScale, 5e4 * uWeightScale) * (1.0 - transmittance);
#else
    vec3 color = accum.a > 0.0 ? accum.rgb * ((1.0 - transmittance) / accum.a) : vec3(0.0);
#endif
    outColor = vec4(color + transmittance * opaque, 1.0);
}
