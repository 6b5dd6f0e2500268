#version 450 core
// Opaque pass: the shaded colour. A MASK material's cut-out is discarded by its wrapped build
// (common/scene_main.glsl) before this runs.
#include "surface.glsl"

layout(location = 0) out vec4 outColor;

void main() {
    outColor = vec4(surfaceColor().rgb, 1.0);
}
