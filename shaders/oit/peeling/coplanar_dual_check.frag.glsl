#version 450 core
// dual-2p, after counting, one draw per side and threshold under GL_SAMPLES_PASSED: passes where
// side uSide (0 front, 1 back) counted at least uMinCount fragments. With uMinCount 2 the host
// lets it zero that side's colour targets (and opacity targets, STRATA_RGB_TRANSMITTANCE) there (for the extraction's MAX blending); with 1 it
// writes nothing. The four counts give the fragments captured without atomics.
#include "peel_bindings.h"

layout(binding = BIND_COPLANAR_COUNT) uniform sampler2D uFrontCount;
layout(binding = BIND_COPLANAR_COUNT + BIND_COPLANAR_BACK_OFFSET) uniform sampler2D uBackCount;
uniform int uSide;
uniform float uMinCount;
layout(location = 0) out vec4 outFrontMin;
layout(location = 1) out vec4 outFrontMax;
layout(location = 2) out vec4 outBackMin;
layout(location = 3) out vec4 outBackMax;
#ifdef STRATA_RGB_TRANSMITTANCE
layout(location = 4) out vec4 outFrontMinOpacity;
layout(location = 5) out vec4 outFrontMaxOpacity;
layout(location = 6) out vec4 outBackMinOpacity;
layout(location = 7) out vec4 outBackMaxOpacity;
#endif

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float count = uSide == 0 ? texelFetch(uFrontCount, pixel, 0).a : texelFetch(uBackCount, pixel, 0).a;
    if (count < uMinCount - 0.5) discard;
    outFrontMin = vec4(0.0);
    outFrontMax = vec4(0.0);
    outBackMin = vec4(0.0);
    outBackMax = vec4(0.0);
#ifdef STRATA_RGB_TRANSMITTANCE
    outFrontMinOpacity = vec4(0.0);
    outFrontMaxOpacity = vec4(0.0);
    outBackMinOpacity = vec4(0.0);
    outBackMaxOpacity = vec4(0.0);
#endif
}
