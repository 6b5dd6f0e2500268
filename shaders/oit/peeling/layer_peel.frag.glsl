#version 450 core
// Peel pass of the coplanarity-aware front-to-back variants (f2b-ll, f2b-fab, f2b-kb): the
// capture pass of layer i (the second pass of Algorithms 2 and 3) and the depth pass of layer
// i + 1 in one geometry pass. Against the layer's anchor (the nearest fragment left, found by
// the last pass), a fragment in front of the opaque depth
//  - nearer than the anchor's tie band was peeled already: discarded;
//  - in the band (layer_tie.glsl) is in this layer, unless the previous layer's band took it
//    (only a fragment nearer than the anchor can be in both): the anchor itself (its object
//    and primitive identify one fragment of a pixel) was kept with its colour by the pass that
//    found it, so only the others, the coincident ones, go into the layer storage, and where
//    nothing coincides no storage is touched; then discarded, so it cannot anchor again;
//  - farther competes, by the hardware depth test (GL_GREATER, writes on, cleared to 0), to
//    anchor the next layer, writing its colour (packed as stored colours are, so the image does
//    not depend on which coincident fragment anchors) and ids where it wins.
// Stores made before a discard stay: discard ends the invocation and drops its outputs, it does
// not undo memory writes already made (the per-pixel-list literature relies on the same). A
// driver that did undo them would lose coincident fragments, which the counts and images of
// tests/coplanar_buffers_gl_test.cpp would show. No early tests: the discards decide what the
// depth test sees. Most fragments cost one texture fetch, two if they
// are not yet peeled; the previous anchor is read only inside the band.
#include "surface.glsl"
#include "peel_bindings.h"
#include "layer_bindings.h"
#include "layer_tie.glsl"
#include "layer_store.glsl"

layout(binding = BIND_OPAQUE_DEPTH) uniform sampler2D uOpaqueDepth;
layout(binding = BIND_PEEL_PREVIOUS) uniform sampler2D uPreviousLayer;
layout(binding = BIND_PEEL_LAYER) uniform sampler2D uLayer;
layout(binding = BIND_ANCHOR) uniform usampler2D uAnchor;
uniform bool uFirstLayer;  // nothing was peeled before this layer

layout(location = 0) out uvec4 outAnchor;  // layer_bindings.h: BIND_ANCHOR

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float z = gl_FragCoord.z;
    float anchor = texelFetch(uLayer, pixel, 0).r;
    if (anchor <= 0.0) discard;  // nothing was left here
    float k = layerKey(z), a = layerKey(anchor);
    bool inBand = sameLayer(k, a);
    if (k > a && !inBand) discard;  // peeled by an earlier layer
    if (z <= texelFetch(uOpaqueDepth, pixel, 0).r) discard;
    uvec2 ids = uvec2(uObjectId + 1u, uint(gl_PrimitiveID));
    if (inBand) {
        bool peeled = k > a && !uFirstLayer && peeledWith(z, texelFetch(uPreviousLayer, pixel, 0).r);
        if (!peeled && texelFetch(uAnchor, pixel, 0).ba != ids) storeLayerFragment(pixel, 0, surfaceColor());
        discard;
    }
    vec4 c = surfaceColor();
    outAnchor = uvec4(packHalf2x16(c.rg), packHalf2x16(c.ba), ids);
}
