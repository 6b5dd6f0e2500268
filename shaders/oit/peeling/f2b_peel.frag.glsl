#version 450 core
// Front-to-back peel pass: among the fragments strictly behind the previous layer (reversed-Z:
// depth strictly less than the last peeled depth) and in front of the opaque depth, the regular
// depth test (GL_GREATER against a per-pass buffer cleared to 0) keeps the nearest.
// FIRST_LAYER (its own program): no previous layer to test against. The total the host peels
// down to comes from a counting pass before (f2b_count.frag.glsl), not from an atomic here: a
// shader that can write memory is depth-tested late (Mesa's llvmpipe and radeonsi test early only
// without memory writes), so every fragment behind the nearest one drawn so far would run it.
// Without, the depth test runs before the shader and rejects them: the first peel at 256x256
// with 8 layers went from 11.5 to 1.5 ms on llvmpipe.
// DEPTH_ONLY (f2b2's pre-pass): no colour output, the shading pass follows with GL_EQUAL.
// No early_fragment_tests: the discards below must happen before the depth write.
#include "surface.glsl"
#include "peel_bindings.h"

layout(binding = BIND_OPAQUE_DEPTH) uniform sampler2D uOpaqueDepth;
#ifndef FIRST_LAYER
layout(binding = BIND_PEEL_PREVIOUS) uniform sampler2D uPreviousDepth;
#endif

#ifndef DEPTH_ONLY
layout(location = 0) out vec4 outColor;
#endif
#if defined(STRATA_RGB_TRANSMITTANCE) && !defined(DEPTH_ONLY)
// A coloured filter's layer: premultiplied colour and what it lets through, per channel.
layout(location = 1) out vec4 outFilter;
#endif

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float z = gl_FragCoord.z;
    if (z <= texelFetch(uOpaqueDepth, pixel, 0).r) discard;
#ifndef FIRST_LAYER
    if (z >= texelFetch(uPreviousDepth, pixel, 0).r) discard;
#endif
#if defined(STRATA_RGB_TRANSMITTANCE) && !defined(DEPTH_ONLY)
    SurfaceOptics o = surfaceOptics();
    outColor = vec4(o.premultiplied, 1.0);
    outFilter = vec4(o.transmittance, 1.0);
#elif !defined(DEPTH_ONLY)
    outColor = surfaceColor();
#endif
}
