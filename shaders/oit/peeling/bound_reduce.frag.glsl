#version 450 core
// Skip queries, step 1: the bound of what remains to peel (f2b: the last peeled depth in r;
// dual: the next nearest depth in r and minus the next farthest in g), reduced to its maximum
// over each uBlock x uBlock block of pixels. The maximum is the conservative side for both
// tests in bounds_query.frag.glsl, so an object tested against its screen rectangle here is
// culled only if a per-pixel test would cull it too, at 1 / uBlock^2 of the fill.
// The block is read 2x2 texels at a time with textureGather (f2b's skip queries on
// builtin:layers:16 at 256x256: 4.8 -> 4.2 ms a frame on llvmpipe, the culling unchanged). At
// an odd edge a gather also reads a texel past the block, wrapped or clamped: a larger maximum,
// still the conservative side. A depth texture gathers (d, 0, 0, 1) per texel, as texelFetch
// reads it.
// NEAR_BOUND_ONLY: the build for a bound whose g no query reads (every technique but dual's):
// it gathers r alone, half the reads.
#include "peel_bindings.h"

layout(binding = BIND_PEEL_PREVIOUS) uniform sampler2D uRemaining;
uniform int uBlock;
layout(location = 0) out vec2 outMax;

void main() {
    ivec2 size = textureSize(uRemaining, 0);
    ivec2 base = ivec2(gl_FragCoord.xy) * uBlock;
    ivec2 end = min(base + uBlock, size);
    vec2 m = vec2(-3.0);  // below every value the bound takes (depths in [0, 1], -2 for none)
    vec2 invSize = 1.0 / vec2(size);
    for (int y = base.y; y < end.y; y += 2)
        for (int x = base.x; x < end.x; x += 2) {
            vec2 corner = vec2(x + 1, y + 1) * invSize;
            vec4 r = textureGather(uRemaining, corner, 0);
#ifdef NEAR_BOUND_ONLY
            vec4 g = vec4(-3.0);
#else
            vec4 g = textureGather(uRemaining, corner, 1);
#endif
            m = max(m, vec2(max(max(r.x, r.y), max(r.z, r.w)), max(max(g.x, g.y), max(g.z, g.w))));
        }
    outMax = m;
}
