#version 450 core
// Peel pass of the coplanarity-aware front-to-back variants (f2b-ll, f2b-fab, f2b-kb): the
// capture pass of layer i (the second pass of Algorithms 2 and 3) and the depth pass of layer
// i + 1 in one geometry pass. A fragment in front of the opaque depth that the previous layer
// did not peel either lies in this layer (within the tie tolerance of the anchor the last pass
// found, layer_tie.glsl) and goes into the layer storage, or lies behind it and competes, by
// the hardware depth test (GL_GREATER, writes on, cleared to 0), to anchor the next layer.
// gl_FragDepth = 0 takes a fragment out of that test (it fails against the cleared buffer);
// writing it rather than discarding keeps the stores of the fragments that leave it.
#include "surface.glsl"
#include "peel_bindings.h"
#include "layer_tie.glsl"
#include "layer_store.glsl"

layout(binding = BIND_OPAQUE_DEPTH) uniform sampler2D uOpaqueDepth;
layout(binding = BIND_PEEL_PREVIOUS) uniform sampler2D uPreviousLayer;
layout(binding = BIND_PEEL_LAYER) uniform sampler2D uLayer;
uniform bool uFirstLayer;  // nothing was peeled before this layer

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float z = gl_FragCoord.z;
    float nextAnchor = 0.0;
    if (z > texelFetch(uOpaqueDepth, pixel, 0).r &&
        (uFirstLayer || !peeledWith(z, texelFetch(uPreviousLayer, pixel, 0).r))) {
        float layer = texelFetch(uLayer, pixel, 0).r;
        if (layer > 0.0 && inLayer(z, layer))
            storeLayerFragment(pixel, 0, surfaceColor());
        else
            nextAnchor = z;
    }
    gl_FragDepth = nextAnchor;
}
