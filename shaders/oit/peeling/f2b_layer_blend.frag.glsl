#version 450 core
// Adds the layer just peeled under what is accumulated (front to back). Pixels without a layer
// are discarded, so the samples-passed count of this pass is the number of fragments captured.
//  - Scalar: the host blends with rgb = dst.a * src.rgb + dst.rgb and a = (1 - src.a) * dst.a,
//    so the target holds the premultiplied colour so far and the transmittance.
//  - STRATA_RGB_TRANSMITTANCE: the transmittance so far is per channel, in a second target,
//    which no blend factor of the colour target can reach; this pass reads it (the one texel it
//    writes, which GL allows between texture barriers) and the host blends the colour additively
//    and the transmittance multiplicatively: colour += T x layer colour, T *= layer filter.
#include "bindings.h"
#include "peel_bindings.h"

layout(binding = BIND_PEEL_PREVIOUS) uniform sampler2D uLayerDepth;
layout(binding = BIND_PEEL_LAYER) uniform sampler2D uLayerColor;
layout(location = 0) out vec4 outColor;
#ifdef STRATA_RGB_TRANSMITTANCE
layout(binding = BIND_PEEL_LAYER_FILTER) uniform sampler2D uLayerFilter;
layout(binding = BIND_PEEL_ACCUM_FILTER) uniform sampler2D uAccumFilter;
layout(location = 1) out vec4 outFilter;
#endif

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    if (texelFetch(uLayerDepth, pixel, 0).r == 0.0) discard;
    vec4 c = texelFetch(uLayerColor, pixel, 0);
#ifdef STRATA_RGB_TRANSMITTANCE
    vec3 transmittance = texelFetch(uAccumFilter, pixel, 0).rgb;
    outColor = vec4(transmittance * c.rgb, 0.0);
    outFilter = vec4(texelFetch(uLayerFilter, pixel, 0).rgb, 1.0);
#else
    outColor = vec4(c.rgb * c.a, c.a);
#endif
}
