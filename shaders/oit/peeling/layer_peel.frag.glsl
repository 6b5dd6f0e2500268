#version 450 core
// Anchor pass of the coplanarity-aware front-to-back variants (f2b-ll, f2b-fab, f2b-kb): f2b's
// peel under the tie rule. A fragment in the current layer's tie band or nearer (layer_tie.glsl)
// was peeled; of the others in front of the opaque depth, the hardware depth test (GL_GREATER,
// writes on, cleared to 0) keeps the nearest, the next layer's anchor, with its colour (packed
// as stored colours are, so the image does not depend on which coincident fragment anchors) and
// its ids. No buffer stores, so a driver may still reject before shading a fragment behind the
// nearest so far, as it does for f2b; the capture pass stores the coincident ones.
#include "surface.glsl"
#include "oit/fragment_color.glsl"
#include "peel_bindings.h"
#include "layer_tie.glsl"

layout(binding = BIND_OPAQUE_DEPTH) uniform sampler2D uOpaqueDepth;
layout(binding = BIND_PEEL_LAYER) uniform sampler2D uLayer;

layout(location = 0) out uvec4 outAnchor;  // layer_bindings.h: BIND_ANCHOR

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float z = gl_FragCoord.z;
    float anchor = texelFetch(uLayer, pixel, 0).r;
    if (anchor <= 0.0 || peeledWith(z, anchor)) discard;
    if (z <= texelFetch(uOpaqueDepth, pixel, 0).r) discard;
    outAnchor = uvec4(storedSurfaceColor().words, uObjectId + 1u, uint(gl_PrimitiveID));
}
