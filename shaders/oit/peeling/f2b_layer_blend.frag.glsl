#version 450 core
// Adds the layer just peeled under what is accumulated (front to back): the host blends with
// rgb = dst.a * src.rgb + dst.rgb and a = (1 - src.a) * dst.a, so the target holds the
// premultiplied colour so far and the transmittance. Pixels without a layer are discarded, so
// the samples-passed count of this pass is the number of fragments captured.
#include "bindings.h"
#include "peel_bindings.h"

layout(binding = BIND_PEEL_PREVIOUS) uniform sampler2D uLayerDepth;
layout(binding = BIND_PEEL_LAYER) uniform sampler2D uLayerColor;
layout(location = 0) out vec4 outColor;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    if (texelFetch(uLayerDepth, pixel, 0).r == 0.0) discard;
    vec4 c = texelFetch(uLayerColor, pixel, 0);
    outColor = vec4(c.rgb * c.a, c.a);
}
