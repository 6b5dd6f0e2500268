#version 450 core
// Capture pass of the coplanarity-aware front-to-back variants (second pass of Algorithms 2
// and 3): every fragment not yet peeled whose depth is in the layer the depth pass anchored
// (within the tie tolerance of its depth) goes into the pixel's layer storage. Early depth test
// against the opaque depth; no colour output.
#include "surface.glsl"
#include "peel_bindings.h"
#include "layer_tie.glsl"
#include "layer_store.glsl"

layout(early_fragment_tests) in;
layout(binding = BIND_PEEL_PREVIOUS) uniform sampler2D uPreviousLayer;
layout(binding = BIND_PEEL_LAYER) uniform sampler2D uLayer;
uniform bool uFirstLayer;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float z = gl_FragCoord.z;
    float layer = texelFetch(uLayer, pixel, 0).r;
    if (layer <= 0.0 || !inLayer(z, layer)) return;
    if (!uFirstLayer && peeledWith(z, texelFetch(uPreviousLayer, pixel, 0).r)) return;
    storeLayerFragment(pixel, 0, surfaceColor());
}
