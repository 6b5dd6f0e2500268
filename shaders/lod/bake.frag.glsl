#version 450 core
// Impostor bake: one texel of the atlas per pixel, rgb = the object-space normal * 0.5 + 0.5,
// a = the depth code (1..255) of the surface kept by the depth test: the one FARTHEST from the
// apex (GL_GREATER, depth 0 at the slab's near plane), nearest a viewer on the view's side.
// PEEL: later peels keep the farthest surface strictly nearer the apex than the previous peel's
// (depth peeling towards the apex; the same triangle gives the same depth by GL's invariance).
// BAKE_ALBEDO: a second target (sRGB-encoded RGBA8) takes what the material's base colour
// texture and COLOR_0 make of the surface there, colour and alpha (glTF's base colour less its
// factor, which the object's draw still applies: common/material.glsl); a MASK material's texels
// below the cutoff are no surface (discarded before the depth test writes).
#include "lod/lod_bindings.h"
#ifdef BAKE_ALBEDO
#include "common/bindings.h"
#include "common/shading_model.h"
#endif

in vec3 vObjectNormal;
in float vSlabT;

#ifdef PEEL
layout(binding = BIND_BAKE_PREVIOUS_DEPTH) uniform sampler2D uPreviousDepth;
#endif

layout(location = 0) out vec4 outTexel;

#ifdef BAKE_ALBEDO
in vec2 vTexCoord;
in vec4 vColor;
layout(binding = BIND_BASE_COLOR_TEXTURE) uniform sampler2D uBaseColorTexture;
uniform bool uTextured;
uniform mat3 uBaseColorTransform;  // KHR_texture_transform
uniform float uFactorAlpha;        // MASK compares factor x texture x COLOR_0 alpha
uniform float uAlphaCutoff;        // with this (0: not MASK)
layout(location = 1) out vec4 outAlbedo;
#endif

void main() {
#ifdef BAKE_ALBEDO
    // Fetched before any discard: the level comes from derivatives, undefined in divergent flow.
    vec4 texel = texture(uBaseColorTexture, transformTexCoord(uBaseColorTransform, vTexCoord));
    if (!uTextured) texel = vec4(1.0);
#endif
#ifdef PEEL
    if (gl_FragCoord.z >= texelFetch(uPreviousDepth, ivec2(gl_FragCoord.xy), 0).r) discard;
#endif
#ifdef BAKE_ALBEDO
    vec4 albedo = texel * vColor;
    if (uAlphaCutoff > 0.0 && uFactorAlpha * albedo.a < uAlphaCutoff) discard;
    outAlbedo = albedo;
#endif
    float codes = float(IMPOSTOR_DEPTH_CODES);
    float code = clamp(floor(clamp(vSlabT, 0.0, 1.0) * codes) + 1.0, 1.0, codes);
    float len = length(vObjectNormal);
    vec3 n = len > 0.0 ? vObjectNormal / len : vec3(0.0, 0.0, 1.0);
    outTexel = vec4(n * 0.5 + 0.5, code / 255.0);
}
