#version 450 core
// Capture pass of the coplanarity-aware front-to-back variants (f2b-ll, f2b-fab, f2b-kb; the
// second pass of Algorithms 2 and 3): every fragment of the layer (within the tie tolerance of
// its anchor, layer_tie.glsl) in front of the opaque depth, not taken by the previous layer's
// band (only one nearer than the anchor can be) and other than the anchor itself (its object
// and primitive identify one fragment of a pixel; the anchor pass kept it with its colour)
// goes into the layer storage. The early depth test (GL_GEQUAL against the band's far edge,
// layer_band.frag.glsl, no writes) rejects everything farther before this shader runs, so where
// nothing coincides the pass costs rasterization and a depth test, and stores nothing.
#include "surface.glsl"
#include "peel_bindings.h"
#include "layer_bindings.h"
#include "layer_tie.glsl"
#include "layer_store.glsl"

STRATA_EARLY_TESTS_NO_SIDE_EFFECTS  // common/scene_prelude.glsl
layout(binding = BIND_OPAQUE_DEPTH) uniform sampler2D uOpaqueDepth;
layout(binding = BIND_PEEL_PREVIOUS) uniform sampler2D uPreviousLayer;
layout(binding = BIND_PEEL_LAYER) uniform sampler2D uLayer;
layout(binding = BIND_ANCHOR) uniform usampler2D uAnchor;
uniform bool uFirstLayer;  // nothing was peeled before this layer

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float z = gl_FragCoord.z;
    float anchor = texelFetch(uLayer, pixel, 0).r;
    if (anchor <= 0.0) return;
    float k = layerKey(z), a = layerKey(anchor);
    if (!sameLayer(k, a)) return;  // peeled already (the early test removed the farther ones)
    if (z <= texelFetch(uOpaqueDepth, pixel, 0).r) return;
    if (k > a && !uFirstLayer && peeledWith(z, texelFetch(uPreviousLayer, pixel, 0).r)) return;
    if (texelFetch(uAnchor, pixel, 0).ba == uvec2(uObjectId + 1u, uint(gl_PrimitiveID))) return;
    storeLayerFragment(pixel, 0, storedSurfaceColor().words);
}
