#version 450 core
// dual: writes the back of the range the init pass found (MAX-blended into the min-max target)
// to the depth buffer the first peel pass tests (dual_back_depth.glsl). Later ranges get theirs
// from the blend's last step or the range pack.
#include "peel_bindings.h"
#include "dual_back_depth.glsl"

layout(binding = BIND_PEEL_PREVIOUS) uniform sampler2D uMinMax;

void main() {
    gl_FragDepth = dualBackDepth(texelFetch(uMinMax, ivec2(gl_FragCoord.xy), 0).rg);
}
