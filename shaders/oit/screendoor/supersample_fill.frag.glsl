#version 450 core
// Starts the supersampled frame as the opaque image: each output pixel's colour and depth
// replicated over its n x n samples, so the transparent fragments depth-test against the opaque
// scene and the 2x2 averages return the opaque colour wherever nothing transparent is kept.
#include "bindings.h"

layout(binding = BIND_OPAQUE_COLOR) uniform sampler2D uOpaqueColor;
layout(binding = BIND_OPAQUE_DEPTH) uniform sampler2D uOpaqueDepth;
uniform ivec2 uTileOrigin;  // output pixels
uniform int uFactor;

layout(location = 0) out vec4 outColor;

void main() {
    ivec2 pixel = uTileOrigin + ivec2(gl_FragCoord.xy) / uFactor;
    outColor = texelFetch(uOpaqueColor, pixel, 0);
    gl_FragDepth = texelFetch(uOpaqueDepth, pixel, 0).r;
}
