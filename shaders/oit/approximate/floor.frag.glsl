#version 450 core
// The floor: every transparent fragment shaded once (the same surfaceColor() every technique
// pays for) and written, unblended, to an RGBA8 scratch target nobody reads. It only measures
// the cheapest possible pass; the output must stay live or the shading is compiled away.
#include "surface.glsl"

layout(location = 0) out vec4 outColor;

void main() {
    vec4 c = surfaceColor();
    outColor = vec4(c.rgb * c.a, c.a);
}
