#version 450 core
// dual-2p counting pass: f2b-2p's (coplanar_count.frag.glsl) from both ends at once. Each
// fragment left is in the front layer (anchored at the nearest left), the back layer (anchored
// at the farthest left) or between them (coplanar_layer.glsl: dualPart). Per side: -(id min),
// id max (MAX) and count (ADD) of the layer's fragments inside the side's open id range, and
// their colour sum (ADD: where the count is 1, the fragment; with STRATA_RGB_TRANSMITTANCE the
// opacity sum besides, coplanar_fragment.glsl). Fragments between put z in the
// front count's b and -z in the back count's b (MAX: the next front and back anchors).
#include "surface.glsl"
#include "coplanar_layer.glsl"
#include "coplanar_ids.glsl"
#include "coplanar_fragment.glsl"

STRATA_EARLY_TESTS_NO_SIDE_EFFECTS  // common/scene_prelude.glsl
layout(binding = BIND_COPLANAR_STATE) uniform sampler2D uFrontState;
layout(binding = BIND_COPLANAR_STATE + BIND_COPLANAR_BACK_OFFSET) uniform sampler2D uBackState;
layout(location = 0) out vec4 outFrontCount;
layout(location = 1) out vec4 outBackCount;
layout(location = 2) out vec4 outFrontColor;
layout(location = 3) out vec4 outBackColor;
#ifdef STRATA_RGB_TRANSMITTANCE
layout(location = 4) out vec4 outFrontOpacity;
layout(location = 5) out vec4 outBackOpacity;
#endif

void sumFragments(FragmentTexels front, FragmentTexels back) {
    outFrontColor = front.color;
    outBackColor = back.color;
#ifdef STRATA_RGB_TRANSMITTANCE
    outFrontOpacity = front.opacity;
    outBackOpacity = back.opacity;
#endif
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec4 front = texelFetch(uFrontState, pixel, 0);
    vec4 back = texelFetch(uBackState, pixel, 0);
    float z = gl_FragCoord.z;
    int part = dualPart(z, front.r, back.r);
    if (part == kPeeled) discard;
    outFrontCount = vec4(kNoId, kNoId, kNoId, 0.0);
    outBackCount = vec4(kNoId, kNoId, kNoId, 0.0);
    if (part == kBetween) {
        sumFragments(kNoFragment, kNoFragment);
        outFrontCount.b = z;
        outBackCount.b = -z;
        return;
    }
    vec2 range = part == kFrontLayer ? front.gb : back.gb;
    float id = fragmentIdKey(uObjectId);
    if (!(id > range.x && id < range.y)) discard;
    vec4 counted = vec4(-id, id, kNoId, 1.0);
    FragmentTexels f = fragmentTexels();
    if (part == kFrontLayer) {
        outFrontCount = counted;
        sumFragments(f, kNoFragment);
    } else {
        outBackCount = counted;
        sumFragments(kNoFragment, f);
    }
}
