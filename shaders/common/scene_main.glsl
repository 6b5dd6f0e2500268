// The real main() of the wrapped variants of every scene program's fragment stage (see
// common/scene_prelude.glsl): the stand-in's and the MASK material's; nothing in the plain build.
// For a stand-in it is the layered impostor's alpha test (Schauffler, section 3.2): the slice
// quad keeps only the atlas texels whose stored depth falls in its interval, widened by
// uImpostorOverlap slice widths on each side (section 3.3, Fig. 4; 0 keeps the intervals
// disjoint so no surface is emitted twice, which transparency needs). The test runs before the
// technique's body, so a rejected texel never reaches a counter, an image store or a colour.
#ifdef STRATA_WRAPPED_MAIN
#undef main
#include "bindings.h"
#include "material.glsl"

#ifdef STRATA_IMPOSTOR
#include "impostor_accept.glsl"

uniform int uImpostorSlices;
uniform float uImpostorOverlap;
// uNormalMatrix: the object's (common/object_record.glsl).
// RGBA8: rgb the object-space normal * 0.5 + 0.5, a the depth code (0 empty, 1..255 the depth
// along the view's slice axis, t = (code - 0.5) / 255 over the slab the slices cover).
layout(binding = BIND_IMPOSTOR_ATLAS) uniform sampler2DArray uImpostorAtlas;
// The same texels' baked albedo (render/stand_in.hpp), where uImpostorAlbedo.
layout(binding = BIND_IMPOSTOR_ALBEDO) uniform sampler2DArray uImpostorAlbedoAtlas;
uniform bool uImpostorAlbedo;

in ImpostorVarying {
    vec2 uv;
    flat ivec2 layer;  // atlas layer, slice
} vImpostor;
#endif

void main() {
#ifdef STRATA_MATERIAL_VARYING
    recordTexCoordDerivatives();  // before any discard (common/material.glsl)
#endif
#ifdef STRATA_IMPOSTOR
    ivec2 size = textureSize(uImpostorAtlas, 0).xy;
    ivec2 texel = clamp(ivec2(vImpostor.uv * vec2(size)), ivec2(0), size - 1);
    vec4 stored = texelFetch(uImpostorAtlas, ivec3(texel, vImpostor.layer.x), 0);
    if (!impostorAccepts(stored.a, vImpostor.layer.y, uImpostorSlices, uImpostorOverlap)) discard;
    strataImpostorNormal = normalize(uNormalMatrix * (stored.rgb * 2.0 - 1.0));
    if (uImpostorAlbedo) strataImpostorAlbedo = texelFetch(uImpostorAlbedoAtlas, ivec3(texel, vImpostor.layer.x), 0);
#endif
#ifdef STRATA_ALPHA_MASK
    // glTF MASK: the fragment exists where factor x texture x COLOR_0 alpha reaches the cutoff.
    strataMaskBaseColor = fetchMaterialBaseColor();
    if (!alphaMaskKeeps(strataMaskBaseColor.a, uAlphaCutoff)) discard;
#endif
    strataSceneFragmentMain();
}
#endif
