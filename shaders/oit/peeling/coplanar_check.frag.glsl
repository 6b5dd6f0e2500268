#version 450 core
// f2b-2p / f2b-3p, after counting: passes (GL_SAMPLES_PASSED) where the layer holds two or more
// fragments still to extract, and zeroes the colour targets there for the extraction's MAX
// blending. No pixel passes: no coplanarity left, the extraction pass is not issued.
#include "peel_bindings.h"

layout(binding = BIND_COPLANAR_COUNT) uniform sampler2D uCount;
layout(location = 0) out vec4 outMin;
layout(location = 1) out vec4 outMax;
#ifdef STRATA_RGB_TRANSMITTANCE
layout(location = 2) out vec4 outMinOpacity;
layout(location = 3) out vec4 outMaxOpacity;
#endif

void main() {
    if (texelFetch(uCount, ivec2(gl_FragCoord.xy), 0).a < 1.5) discard;
    outMin = vec4(0.0);
    outMax = vec4(0.0);
#ifdef STRATA_RGB_TRANSMITTANCE
    outMinOpacity = vec4(0.0);
    outMaxOpacity = vec4(0.0);
#endif
}
