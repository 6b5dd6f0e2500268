#version 450 core
// One step of the box filter: each destination texel is the mean of the 2x2 source texels it
// covers (Sen et al. 4.1.3, as mip-map generation). log2(n) steps make an n x n box.
#include "screendoor_bindings.h"

layout(binding = BIND_DOWNSAMPLE_SOURCE) uniform sampler2D uSource;  // base level = the source level
uniform ivec2 uDestinationOrigin;  // where the destination's (0, 0) lies in the bound viewport

layout(location = 0) out vec4 outColor;

void main() {
    ivec2 p = 2 * (ivec2(gl_FragCoord.xy) - uDestinationOrigin);
    vec4 sum = texelFetch(uSource, p, 0) + texelFetch(uSource, p + ivec2(1, 0), 0) +
               texelFetch(uSource, p + ivec2(0, 1), 0) + texelFetch(uSource, p + ivec2(1, 1), 0);
    outColor = 0.25 * sum;
}
