#version 450 core
// First depth pass of the coplanarity-aware front-to-back variants (f2b-ll, f2b-fab, f2b-kb):
// the hardware depth test (GL_GREATER, writes on, cleared to 0) keeps each pixel's nearest
// transparent fragment in front of the opaque depth, the anchor of the first layer, with its
// colour and ids (layer_bindings.h), and every such fragment is counted: the total
// the host peels down to. Later anchors come from the peel passes (layer_peel.frag.glsl). No
// early tests: the discard must come first.
#include "surface.glsl"
#include "oit/fragment_color.glsl"
#include "oit/subgroup_counter.glsl"

layout(binding = BIND_OPAQUE_DEPTH) uniform sampler2D uOpaqueDepth;
layout(binding = BIND_COUNTERS, offset = 0) uniform atomic_uint uTotal;
layout(location = 0) out uvec4 outAnchor;  // layer_bindings.h: BIND_ANCHOR

void main() {
    if (gl_FragCoord.z <= texelFetch(uOpaqueDepth, ivec2(gl_FragCoord.xy), 0).r) discard;
    subgroupCounterIncrement(uTotal);
    outAnchor = uvec4(storedSurfaceColor().words, uObjectId + 1u, uint(gl_PrimitiveID));
}
