#version 450 core
// f2b-3p depth pass: the nearest fragment beyond the current layer (GL_GREATER with depth
// writes into a buffer cleared to 0), the next layer's anchor. The opaque test is done here:
// the hardware depth buffer is this pass's own. No colour output.
#include "bindings.h"
#include "coplanar_layer.glsl"

layout(binding = BIND_OPAQUE_DEPTH) uniform sampler2D uOpaqueDepth;
layout(binding = BIND_COPLANAR_STATE) uniform sampler2D uState;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float z = gl_FragCoord.z;
    if (z <= texelFetch(uOpaqueDepth, pixel, 0).r) discard;
    float anchor = texelFetch(uState, pixel, 0).r;
    if (!hasAnchor(anchor) || z > anchor || inLayerOf(z, anchor)) discard;
}
