#version 450 core
// Skip queries, step 1: the bound of what remains to peel (f2b: the last peeled depth in r;
// dual: the next nearest depth in r and minus the next farthest in g), reduced to its maximum
// over each uBlock x uBlock block of pixels. The maximum is the conservative side for both
// tests in bounds_query.frag.glsl, so an object tested against its screen rectangle here is
// culled only if a per-pixel test would cull it too, at 1 / uBlock^2 of the fill.
#include "peel_bindings.h"

layout(binding = BIND_PEEL_PREVIOUS) uniform sampler2D uRemaining;
uniform int uBlock;
layout(location = 0) out vec2 outMax;

void main() {
    ivec2 size = textureSize(uRemaining, 0);
    ivec2 base = ivec2(gl_FragCoord.xy) * uBlock;
    ivec2 end = min(base + uBlock, size);
    vec2 m = vec2(-3.0);  // below every value the bound takes (depths in [0, 1], -2 for none)
    for (int y = base.y; y < end.y; ++y)
        for (int x = base.x; x < end.x; ++x) m = max(m, texelFetch(uRemaining, ivec2(x, y), 0).rg);
    outMax = m;
}
