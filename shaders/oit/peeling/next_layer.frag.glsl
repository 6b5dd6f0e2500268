#version 450 core
// First depth pass of the coplanarity-aware front-to-back variants (f2b-ll, f2b-fab, f2b-kb):
// the hardware depth test (GL_GREATER, writes on, cleared to 0) keeps each pixel's nearest
// transparent fragment in front of the opaque depth, the anchor of the first layer, with its
// colour and its (object id + 1, primitive id), and every such fragment is counted: the total
// the host peels down to. Later anchors come from the peel passes (layer_peel.frag.glsl). No
// early tests: the discard must come first.
#include "surface.glsl"
#include "oit/packed_color.glsl"

layout(binding = BIND_OPAQUE_DEPTH) uniform sampler2D uOpaqueDepth;
layout(binding = BIND_COUNTERS, offset = 0) uniform atomic_uint uTotal;
layout(location = 0) out vec4 outAnchorColor;
layout(location = 1) out uvec2 outAnchorIds;

void main() {
    if (gl_FragCoord.z <= texelFetch(uOpaqueDepth, ivec2(gl_FragCoord.xy), 0).r) discard;
    atomicCounterIncrement(uTotal);
    outAnchorColor = packedPrecision(surfaceColor());
    outAnchorIds = uvec2(uObjectId + 1u, uint(gl_PrimitiveID));
}
