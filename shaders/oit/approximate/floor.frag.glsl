#version 450 core
// The floor: every transparent fragment shaded once (the same surfaceColor() every technique
// pays for) and added with (ONE, ONE) blending. Output = opaque + sum of alpha * colour: an
// order-independent sum, not transparency; it only measures the cheapest possible pass.
#include "surface.glsl"

layout(location = 0) out vec4 outColor;

void main() {
    vec4 c = surfaceColor();
    outColor = vec4(c.rgb * c.a, 0.0);
}
