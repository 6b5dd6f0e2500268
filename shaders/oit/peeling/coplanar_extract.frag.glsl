#version 450 core
// f2b-2p / f2b-3p extraction (f2b-3p: its shading pass), at pixels whose layer holds two or
// more fragments: those whose ids the counting pass found, the smallest into target 0 and the
// largest into target 1 (with STRATA_RGB_TRANSMITTANCE their opacities into targets 2 and 3;
// coplanar_fragment.glsl) (MAX blending over targets the host zeroed with glClearTexImage: at
// most one fragment per pixel writes each, since a pixel has one fragment per (object,
// primitive)). A single fragment came with its colour (the counting pass's SUM_COLOR), and the
// resolve before this pass took it: such pixels are discarded here by their count.
// BAND_DEPTH (f2b-3p): the depth attachment holds the layer band's far edge (coplanar_band), not
// the opaque depth, so the opaque test is done here. The shader writes no memory and no depth,
// so a driver still tests depth before it runs and, where a layer holds two or more, only the
// layer's fragments are shaded. At a pixel the first resolve closed, the band has moved to the
// next layer already (BAND_OUT); its fragments there cost one count fetch, then the discard.
#include "surface.glsl"
#include "coplanar_layer.glsl"
#include "coplanar_ids.glsl"
#include "coplanar_fragment.glsl"

STRATA_EARLY_TESTS_NO_SIDE_EFFECTS  // common/scene_prelude.glsl
layout(binding = BIND_COPLANAR_STATE) uniform sampler2D uState;
#ifdef BAND_DEPTH
layout(binding = BIND_OPAQUE_DEPTH) uniform sampler2D uOpaqueDepth;
#endif
layout(binding = BIND_COPLANAR_COUNT) uniform sampler2D uCount;
layout(location = 0) out vec4 outMin;
layout(location = 1) out vec4 outMax;
#ifdef STRATA_RGB_TRANSMITTANCE
layout(location = 2) out vec4 outMinOpacity;
layout(location = 3) out vec4 outMaxOpacity;
#endif

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec4 count = texelFetch(uCount, pixel, 0);
    if (count.a < 1.5) discard;
    float anchor = texelFetch(uState, pixel, 0).r;
    float z = gl_FragCoord.z;
#ifdef BAND_DEPTH
    if (z <= texelFetch(uOpaqueDepth, ivec2(gl_FragCoord.xy), 0).r) discard;  // the attachment is the band's
#endif
    if (!hasAnchor(anchor) || z > anchor || !inLayerOf(z, anchor)) discard;
    float id = fragmentIdKey(uObjectId);
    bool isMin = id == -count.r;
    bool isMax = id == count.g && !isMin;
    if (!isMin && !isMax) discard;
    FragmentTexels f = fragmentTexels();
    FragmentTexels none = kNoFragment;
    outMin = isMin ? f.color : none.color;
    outMax = isMax ? f.color : none.color;
#ifdef STRATA_RGB_TRANSMITTANCE
    outMinOpacity = isMin ? f.opacity : none.opacity;
    outMaxOpacity = isMax ? f.opacity : none.opacity;
#endif
}
