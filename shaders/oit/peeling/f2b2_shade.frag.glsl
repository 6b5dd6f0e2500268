#version 450 core
// f2b2 shading pass: the depth pre-pass left the layer's depth in the buffer; GL_EQUAL with
// early tests shades only the fragment at that depth (a stencil test lets one of several
// coincident ones through, like f2b's strict test does) and blends it under the accumulation.
// STRATA_RGB_TRANSMITTANCE: as f2b's layer pass (f2b_layer_blend.frag.glsl), the fragment reads
// the accumulated transmittance per channel, its own texel, and the host blends the colour
// additively and the transmittance multiplicatively. Early tests let one fragment per pixel be
// shaded, so the texel is read and written once; a MASK build (late tests: its discard comes
// first) may shade the stencil's losers too, whose reads are then undefined but whose writes the
// stencil test drops.
#include "surface.glsl"
#include "peel_bindings.h"

STRATA_EARLY_TESTS_NO_SIDE_EFFECTS  // common/scene_prelude.glsl
layout(location = 0) out vec4 outColor;
#ifdef STRATA_RGB_TRANSMITTANCE
layout(binding = BIND_PEEL_ACCUM_FILTER) uniform sampler2D uAccumFilter;
layout(location = 1) out vec4 outFilter;
#endif

void main() {
#ifdef STRATA_RGB_TRANSMITTANCE
    SurfaceOptics o = surfaceOptics();
    outColor = vec4(texelFetch(uAccumFilter, ivec2(gl_FragCoord.xy), 0).rgb * o.premultiplied, 0.0);
    outFilter = vec4(o.transmittance, 1.0);
#else
    vec4 c = surfaceColor();
    outColor = vec4(c.rgb * c.a, c.a);
#endif
}
