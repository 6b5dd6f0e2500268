#version 450 core
// Full-screen pass of the coplanarity-aware front-to-back variants: writes the far edge of the
// current layer's tie band (layer_tie.glsl) as depth, so that the capture pass can test
// GL_GEQUAL against it early, before its shader (which may store), and run that shader only for
// the layer's fragments and the few peeled ones the skip queries left. No layer: 1 (the near
// plane), which lets nothing further through.
#include "peel_bindings.h"
#include "layer_tie.glsl"

layout(binding = BIND_PEEL_LAYER) uniform sampler2D uLayer;

void main() {
    float anchor = texelFetch(uLayer, ivec2(gl_FragCoord.xy), 0).r;
    gl_FragDepth = anchor > 0.0 ? layerFarEdge(anchor) : 1.0;
}
