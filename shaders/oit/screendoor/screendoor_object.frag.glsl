#version 450 core
// Object-space screen-door transparency, hardware version (Sen et al. 4.2): the mask of the
// triangle's alpha level, mapped on the triangle by object_mask.geom.glsl, keeps or rejects the
// fragment; a kept fragment is written opaque. The geometry stage renames the normal
// (gWorldNormal), so the material comes from material.glsl, not via surface.glsl; the mask
// level is the fragment's alpha (texture and vertex colour included).
//
// Silhouettes: read nearest, a sample sees one texel however many the surface puts under it
// where it turns away, so the hardware version shows no silhouette opacity (the paper's section
// 5), and the paper asks for a Max filter. This is one: the sample's footprint in mask texels is
// the parallelogram spanned by dFdx and dFdy of the mask coordinate; the mask is read at
// m_x x m_y points spread over it, and the sample is kept if any of them is. m is |dFdx| (and
// |dFdy|) rounded down or up at random per sample (a hash of the sample's position and the
// seed: reproducible, order independent) so that its mean is the footprint's extent, at least 1.
// A surface facing the eye (a footprint of one texel) reads its nearest texel, as before; a
// footprint of n texels keeps about 1 - (1 - alpha)^n of its samples, the thin shell's opacity.
#include "shading.glsl"
// alpha_mask.glsl brings random_hash.glsl (hashUint, hashUnit) too.
#include "alpha_mask.glsl"
#include "shade_material.glsl"

in vec3 gWorldNormal;
in vec3 gWorldPosition;
in vec2 gMaskCoord;

layout(location = 0) out vec4 outColor;

// At most this many reads a side: past 8 texels a side the sample is kept with probability
// 1 - (1 - alpha)^64 or more, opaque for any alpha worth drawing.
const int kMaxReadsPerSide = 8;

bool footprintKeeps(vec2 coord, vec2 dx, vec2 dy, float alpha) {
    // A footprint of at most one texel a side (a surface facing the eye, most of a scene): the
    // nearest texel, without the hash (past 1 + 1e-3 a second read would be drawn for fewer than
    // 0.1 % of the samples).
    if (max(length(dx), length(dy)) <= 1.001) return maskKeeps(ivec2(floor(coord)), alpha);
    uint h = hashUint(hashUint(uSeed ^ uint(gl_FragCoord.x)) ^ (uint(gl_FragCoord.y) * 0x9E3779B9u));
    int nx = clamp(int(floor(length(dx) + hashUnit(h))), 1, kMaxReadsPerSide);
    int ny = clamp(int(floor(length(dy) + hashUnit(hashUint(h)))), 1, kMaxReadsPerSide);
    bool keep = false;
    for (int i = 0; i < nx; ++i)
        for (int j = 0; j < ny; ++j) {
            vec2 p = coord + dx * ((float(i) + 0.5) / float(nx) - 0.5) + dy * ((float(j) + 0.5) / float(ny) - 0.5);
            keep = keep || maskKeeps(ivec2(floor(p)), alpha);
        }
    return keep;
}

void main() {
#ifdef STRATA_WRAPPED_MAIN
    // A stand-in's slice quads and a MASK material went through the wrapper's alpha test
    // (common/scene_main.glsl), whose discard leaves derivatives undefined here: central
    // differences of the interpolant one pixel apart instead, which is what dFdx and dFdy estimate.
    vec2 dx = interpolateAtOffset(gMaskCoord, vec2(0.5, 0.0)) - interpolateAtOffset(gMaskCoord, vec2(-0.5, 0.0));
    vec2 dy = interpolateAtOffset(gMaskCoord, vec2(0.0, 0.5)) - interpolateAtOffset(gMaskCoord, vec2(0.0, -0.5));
#else
    // Derivatives first, in uniform control flow.
    vec2 dx = dFdx(gMaskCoord), dy = dFdy(gMaskCoord);
#endif
    vec4 base = materialBaseColor();  // before the discard: a texture fetch takes derivatives too
    if (!footprintKeeps(gMaskCoord, dx, dy, base.a)) discard;
    outColor = vec4(shadeMaterial(base.rgb, kStandIn ? strataImpostorNormal : gWorldNormal, gWorldPosition), 1.0);
}
