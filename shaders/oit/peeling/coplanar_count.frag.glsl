#version 450 core
// f2b-2p / f2b-3p counting pass (Algorithm 1's pass with MAX and ADD blending). Of the fragments
// left in the layer anchored at the state's r (coplanar_layer.glsl) whose id lies strictly
// inside the state's open id range (g, b), it leaves in the count target: -(smallest id),
// largest id (MAX) and how many (ADD, alpha).
// NEXT_ANCHOR (f2b-2p): fragments beyond the layer put their depth in b (MAX: the nearest one),
//   the anchor of the next layer, so f2b-2p needs no depth pass.
// BAND_DEPTH (f2b-3p): the depth attachment holds the layer band's far edge (coplanar_band), not
//   the opaque depth, so the opaque test is done here; fragments behind the band never run.
// SUM_COLOR: the layer's fragments add their colour into target 1 (with
//   STRATA_RGB_TRANSMITTANCE their opacity into target 2, coplanar_fragment.glsl). Where the
//   count is 1, that sum is the fragment: the pixel needs no extraction pass (no coplanarity,
//   no cost). f2b-3p's sum is of the band's survivors, its layer only.
#include "surface.glsl"
#include "coplanar_layer.glsl"
#include "coplanar_ids.glsl"
#include "coplanar_fragment.glsl"

STRATA_EARLY_TESTS_NO_SIDE_EFFECTS  // common/scene_prelude.glsl
layout(binding = BIND_COPLANAR_STATE) uniform sampler2D uState;
#ifdef BAND_DEPTH
layout(binding = BIND_OPAQUE_DEPTH) uniform sampler2D uOpaqueDepth;
#endif
layout(location = 0) out vec4 outCount;
#ifdef SUM_COLOR
layout(location = 1) out vec4 outColor;
#ifdef STRATA_RGB_TRANSMITTANCE
layout(location = 2) out vec4 outOpacity;
#endif
void sumFragment(FragmentTexels f) {
    outColor = f.color;
#ifdef STRATA_RGB_TRANSMITTANCE
    outOpacity = f.opacity;
#endif
}
#endif

void main() {
    vec4 state = texelFetch(uState, ivec2(gl_FragCoord.xy), 0);
    float z = gl_FragCoord.z;
#ifdef BAND_DEPTH
    if (z <= texelFetch(uOpaqueDepth, ivec2(gl_FragCoord.xy), 0).r) discard;  // the attachment is the band's
#endif
    if (!hasAnchor(state.r) || z > state.r) discard;  // nothing left here, or peeled already
    if (!inLayerOf(z, state.r)) {
#ifdef NEXT_ANCHOR
        outCount = vec4(kNoId, kNoId, z, 0.0);
#ifdef SUM_COLOR
        sumFragment(kNoFragment);
#endif
        return;
#else
        discard;
#endif
    }
    float id = fragmentIdKey(uObjectId);
    if (!(id > state.g && id < state.b)) discard;  // extracted by an earlier pass of this layer
    outCount = vec4(-id, id, kNoId, 1.0);
#ifdef SUM_COLOR
    sumFragment(fragmentTexels());
#endif
}
