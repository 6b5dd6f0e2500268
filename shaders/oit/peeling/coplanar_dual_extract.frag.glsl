#version 450 core
// dual-2p extraction: where a side's layer holds two or more, its id-min and id-max fragments'
// colours (MAX blending over targets the check zeroed; one fragment per pixel writes each),
// with STRATA_RGB_TRANSMITTANCE their opacities too (coplanar_fragment.glsl).
#include "surface.glsl"
#include "coplanar_layer.glsl"
#include "coplanar_ids.glsl"
#include "coplanar_fragment.glsl"

STRATA_EARLY_TESTS_NO_SIDE_EFFECTS  // common/scene_prelude.glsl
layout(binding = BIND_COPLANAR_STATE) uniform sampler2D uFrontState;
layout(binding = BIND_COPLANAR_STATE + BIND_COPLANAR_BACK_OFFSET) uniform sampler2D uBackState;
layout(binding = BIND_COPLANAR_COUNT) uniform sampler2D uFrontCount;
layout(binding = BIND_COPLANAR_COUNT + BIND_COPLANAR_BACK_OFFSET) uniform sampler2D uBackCount;
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
    int part = dualPart(gl_FragCoord.z, texelFetch(uFrontState, pixel, 0).r, texelFetch(uBackState, pixel, 0).r);
    if (part != kFrontLayer && part != kBackLayer) discard;
    vec4 count = part == kFrontLayer ? texelFetch(uFrontCount, pixel, 0) : texelFetch(uBackCount, pixel, 0);
    if (count.a < 1.5) discard;
    float id = fragmentIdKey(uObjectId);
    bool isMin = id == -count.r;
    bool isMax = id == count.g && !isMin;
    if (!isMin && !isMax) discard;
    FragmentTexels f = fragmentTexels();
    FragmentTexels none = kNoFragment;
    bool front = part == kFrontLayer;
    outFrontMin = front && isMin ? f.color : none.color;
    outFrontMax = front && isMax ? f.color : none.color;
    outBackMin = !front && isMin ? f.color : none.color;
    outBackMax = !front && isMax ? f.color : none.color;
#ifdef STRATA_RGB_TRANSMITTANCE
    outFrontMinOpacity = front && isMin ? f.opacity : none.opacity;
    outFrontMaxOpacity = front && isMax ? f.opacity : none.opacity;
    outBackMinOpacity = !front && isMin ? f.opacity : none.opacity;
    outBackMaxOpacity = !front && isMax ? f.opacity : none.opacity;
#endif
}
