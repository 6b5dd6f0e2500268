#version 450 core
// Opaque pass: shaded colour; MASK materials drop fragments below the cutoff.
#include "surface.glsl"

layout(location = 0) out vec4 outColor;

void main() {
    if (uAlpha < uAlphaCutoff) discard;
    outColor = vec4(surfaceColor().rgb, 1.0);
}
