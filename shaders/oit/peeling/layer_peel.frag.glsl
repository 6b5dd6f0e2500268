#version 450 core
// Peel pass of the coplanarity-aware front-to-back variants (f2b-ll, f2b-fab, f2b-kb): the
// capture pass of layer i (the second pass of Algorithms 2 and 3) and the depth pass of layer
// i + 1 in one geometry pass. A fragment in front of the opaque depth that the previous layer
// did not peel either
//  - lies in this layer (within the tie tolerance of its anchor, layer_tie.glsl): the anchor
//    itself (its object and primitive, which identify one fragment of a pixel) was kept with
//    its colour by the pass that found it, so only the others, the coincident ones, go into the
//    layer storage: where nothing coincides no storage is touched; or
//  - lies behind it and competes, by the hardware depth test (GL_GREATER, writes on, cleared to
//    0), to anchor the next layer, writing its colour (rounded as stored colours are, so the
//    image does not depend on which coincident fragment anchors) and ids where it wins.
// gl_FragDepth = 0 takes a fragment out of that test (it fails against the cleared buffer);
// writing it rather than discarding keeps the stores of the fragments that leave it.
#include "surface.glsl"
#include "oit/packed_color.glsl"
#include "peel_bindings.h"
#include "layer_bindings.h"
#include "layer_tie.glsl"
#include "layer_store.glsl"

layout(binding = BIND_OPAQUE_DEPTH) uniform sampler2D uOpaqueDepth;
layout(binding = BIND_PEEL_PREVIOUS) uniform sampler2D uPreviousLayer;
layout(binding = BIND_PEEL_LAYER) uniform sampler2D uLayer;
layout(binding = BIND_ANCHOR_IDS) uniform usampler2D uAnchorIds;
uniform bool uFirstLayer;  // nothing was peeled before this layer

layout(location = 0) out vec4 outAnchorColor;
layout(location = 1) out uvec2 outAnchorIds;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float z = gl_FragCoord.z;
    uvec2 ids = uvec2(uObjectId + 1u, uint(gl_PrimitiveID));
    float nextAnchor = 0.0;
    outAnchorColor = vec4(0.0);
    outAnchorIds = uvec2(0u);
    if (z > texelFetch(uOpaqueDepth, pixel, 0).r &&
        (uFirstLayer || !peeledWith(z, texelFetch(uPreviousLayer, pixel, 0).r))) {
        float layer = texelFetch(uLayer, pixel, 0).r;
        if (layer > 0.0 && inLayer(z, layer)) {
            if (texelFetch(uAnchorIds, pixel, 0).rg != ids) storeLayerFragment(pixel, 0, surfaceColor());
        } else {
            nextAnchor = z;
            outAnchorColor = packedPrecision(surfaceColor());
            outAnchorIds = ids;
        }
    }
    gl_FragDepth = nextAnchor;
}
