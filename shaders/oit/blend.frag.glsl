#version 450 core
// Fixed-function "over" blending, correct only when fragments arrive back to front.
//  - Scalar: (SRC_ALPHA, ONE_MINUS_SRC_ALPHA).
//  - STRATA_RGB_TRANSMITTANCE (a scene with coloured filters): dual-source blending, colour =
//    source 0 + source 1 x destination per channel, with the premultiplied colour in source 0
//    and what the fragment lets through in source 1: glass filters what lies behind it per
//    channel, and every other fragment blends as the scalar build does.
#include "surface.glsl"

#ifdef STRATA_RGB_TRANSMITTANCE
layout(location = 0, index = 0) out vec4 outColor;
layout(location = 0, index = 1) out vec4 outPasses;

void main() {
    SurfaceOptics o = surfaceOptics();
    outColor = vec4(o.premultiplied, 0.0);
    outPasses = vec4(o.transmittance, 1.0);
}
#else
layout(location = 0) out vec4 outColor;

void main() {
    outColor = surfaceColor();
}
#endif
