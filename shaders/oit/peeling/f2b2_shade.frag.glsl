#version 450 core
// f2b2 shading pass: the depth pre-pass left the layer's depth in the buffer; GL_EQUAL with
// early tests shades only the fragment at that depth (a stencil test lets one of several
// coincident ones through, like f2b's strict test does) and blends it under the accumulation.
#include "surface.glsl"

STRATA_EARLY_TESTS_NO_SIDE_EFFECTS  // common/scene_prelude.glsl
layout(location = 0) out vec4 outColor;

void main() {
    vec4 c = surfaceColor();
    outColor = vec4(c.rgb * c.a, c.a);
}
