#version 450 core
// First depth pass of the coplanarity-aware front-to-back variants (f2b-ll, f2b-fab, f2b-kb):
// the hardware depth test (GL_GREATER, writes on, cleared to 0) keeps each pixel's nearest
// transparent fragment in front of the opaque depth, the anchor of the first layer, and every
// such fragment is counted: the total the host peels down to. Later anchors come from the
// capture passes (layer_peel.frag.glsl). No early tests: the discard must come first.
#include "bindings.h"

layout(binding = BIND_OPAQUE_DEPTH) uniform sampler2D uOpaqueDepth;
layout(binding = BIND_COUNTERS, offset = 0) uniform atomic_uint uTotal;

void main() {
    if (gl_FragCoord.z <= texelFetch(uOpaqueDepth, ivec2(gl_FragCoord.xy), 0).r) discard;
    atomicCounterIncrement(uTotal);
}
