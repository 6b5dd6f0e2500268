#version 450 core
// Depth pass of the coplanarity-aware front-to-back variants (f2b-ll, f2b-fab, f2b-kb; the
// first pass of Algorithm 2): among the fragments in front of the opaque depth that the
// previous layer did not peel (layer_tie.glsl), the hardware depth test (GL_GREATER, writes on,
// cleared to 0) keeps the nearest: the anchor of the next layer. The first pass also counts every
// fragment, the total the host peels down to. No early tests: the discards must come first.
#include "bindings.h"
#include "peel_bindings.h"
#include "layer_tie.glsl"

layout(binding = BIND_OPAQUE_DEPTH) uniform sampler2D uOpaqueDepth;
layout(binding = BIND_PEEL_PREVIOUS) uniform sampler2D uPreviousLayer;
layout(binding = BIND_COUNTERS, offset = 0) uniform atomic_uint uTotal;
uniform bool uFirstLayer;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float z = gl_FragCoord.z;
    if (z <= texelFetch(uOpaqueDepth, pixel, 0).r) discard;
    if (uFirstLayer)
        atomicCounterIncrement(uTotal);
    else if (peeledWith(z, texelFetch(uPreviousLayer, pixel, 0).r))
        discard;
}
