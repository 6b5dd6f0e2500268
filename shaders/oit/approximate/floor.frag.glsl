#version 450 core
// The floor: every transparent fragment shaded once (the same surfaceColor() every technique
// pays for) and written, unblended, to an R8 scratch target nobody reads. It only measures the
// cheapest possible pass. The one channel written depends on every component of the colour,
// so the shading stays live and is not compiled away.
#include "surface.glsl"

layout(location = 0) out vec4 outColor;

void main() {
    vec4 c = surfaceColor();
    outColor = vec4(dot(c.rgb, vec3(c.a)));
}
