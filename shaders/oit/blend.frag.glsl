#version 450 core
// Fixed-function "over" blending (SRC_ALPHA, ONE_MINUS_SRC_ALPHA): correct only when
// fragments arrive back to front.
#include "surface.glsl"

layout(location = 0) out vec4 outColor;

void main() {
    outColor = surfaceColor();
}
