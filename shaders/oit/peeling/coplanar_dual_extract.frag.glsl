#version 450 core
// dual-2p extraction: where a side's layer holds two or more, its id-min and id-max fragments'
// colours (MAX blending over targets the check zeroed; one fragment per pixel writes each).
#include "surface.glsl"
#include "coplanar_layer.glsl"
#include "coplanar_ids.glsl"

STRATA_EARLY_TESTS_NO_SIDE_EFFECTS  // common/scene_prelude.glsl
layout(binding = BIND_COPLANAR_STATE) uniform sampler2D uFrontState;
layout(binding = BIND_COPLANAR_STATE + BIND_COPLANAR_BACK_OFFSET) uniform sampler2D uBackState;
layout(binding = BIND_COPLANAR_COUNT) uniform sampler2D uFrontCount;
layout(binding = BIND_COPLANAR_COUNT + BIND_COPLANAR_BACK_OFFSET) uniform sampler2D uBackCount;
layout(location = 0) out vec4 outFrontMin;
layout(location = 1) out vec4 outFrontMax;
layout(location = 2) out vec4 outBackMin;
layout(location = 3) out vec4 outBackMax;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    int part = dualPart(gl_FragCoord.z, texelFetch(uFrontState, pixel, 0).r, texelFetch(uBackState, pixel, 0).r);
    if (part != kFrontLayer && part != kBackLayer) discard;
    vec4 count = part == kFrontLayer ? texelFetch(uFrontCount, pixel, 0) : texelFetch(uBackCount, pixel, 0);
    if (count.a < 1.5) discard;
    float id = fragmentIdKey(uObjectId);
    bool isMin = id == -count.r;
    bool isMax = id == count.g && !isMin;
    if (!isMin && !isMax) discard;
    vec4 c = surfaceColor();
    bool front = part == kFrontLayer;
    outFrontMin = front && isMin ? c : vec4(0.0);
    outFrontMax = front && isMax ? c : vec4(0.0);
    outBackMin = !front && isMin ? c : vec4(0.0);
    outBackMax = !front && isMax ? c : vec4(0.0);
}
