// A fragment's material inputs as the glTF material defines them (common/shading_model.h does
// the arithmetic, shared with the CPU reference): base colour and alpha (factor x base colour
// texture x COLOR_0), metallic and roughness, occlusion, emission, and the normal-mapped normal.
// Which parts exist is decided when the program is built, per material
// (render/scene_program.hpp, SceneProgram::variant): a factor-only material is drawn by a build
// with no texture fetch, no vertex colour and no branch.
//   STRATA_BASE_COLOR_TEXTURE          base colour texture (sRGB, decoded by the GL_SRGB8_ALPHA8 texture)
//   STRATA_VERTEX_COLOR                the mesh has COLOR_0
//   STRATA_METALLIC_ROUGHNESS_TEXTURE  metallic (blue) and roughness (green), linear
//   STRATA_NORMAL_TEXTURE              tangent-space normal map, linear; the mesh's tangents
//   STRATA_OCCLUSION_TEXTURE           ambient occlusion (red), linear
//   STRATA_EMISSIVE_TEXTURE            emission (sRGB)
//   STRATA_ALPHA_MASK                  MASK: common/scene_main.glsl discards below the cutoff
//   STRATA_UNLIT                       KHR_materials_unlit (common/surface.glsl skips the light)
//   STRATA_TRANSMISSION                KHR_materials_transmission and _ior (common/surface.glsl's
//                                      SurfaceOptics); without it transmission is 0 and ior 1.5
#ifndef STRATA_MATERIAL_GLSL
#define STRATA_MATERIAL_GLSL
#include "bindings.h"
#include "shading_model.h"
#include "material_features.glsl"
#include "object_record.glsl"

uniform vec3 uBaseColor;
uniform float uAlpha;
uniform float uAlphaCutoff;
uniform float uMetallic;
uniform float uRoughness;
uniform vec3 uEmissive;  // emissiveFactor x KHR_materials_emissive_strength
#ifdef STRATA_TRANSMISSION
uniform float uTransmission;
uniform float uIor;
// uVolumeFilter, exp(-tau x thickness) through the medium per channel, is the object's
// (common/object_record.glsl).
uniform bool uAlphaBlend;    // BLEND: alpha is coverage; OPAQUE glass covers its whole surface
#endif

#ifdef STRATA_MATERIAL_VARYING
// Written by common/scene.vert.glsl (and passed on by a geometry stage under the same name).
in MaterialVarying {
    vec2 texCoord0;
    vec2 texCoord1;
    vec4 color;
#ifdef STRATA_NORMAL_TEXTURE
    vec4 tangent;  // world space, w the bitangent's sign
#endif
} vMaterial;

// A texture's coordinate: its TEXCOORD set, through its KHR_texture_transform.
vec2 materialTexCoord(mat3 transform, int texCoord) {
    return transformTexCoord(transform, texCoord == 0 ? vMaterial.texCoord0 : vMaterial.texCoord1);
}

#ifdef STRATA_WRAPPED_MAIN
// A wrapped variant (MASK, stand-in) may discard in common/scene_main.glsl before the stage's own
// fetches run, and after a discard that not every fragment of a quad takes, implicit derivatives
// are undefined (GLSL 4.50, 8.9.1). The wrapper records both coordinate sets' derivatives first
// (xy: d/dx, zw: d/dy), and every material fetch takes them explicitly.
vec4 strataTexCoordGrad[2];
void recordTexCoordDerivatives() {
    strataTexCoordGrad[0] = vec4(dFdx(vMaterial.texCoord0), dFdy(vMaterial.texCoord0));
    strataTexCoordGrad[1] = vec4(dFdx(vMaterial.texCoord1), dFdy(vMaterial.texCoord1));
}
#endif

// A material texture at its coordinate: texture() in a plain build, textureGrad with the
// recorded derivatives (through the transform's linear part) in a wrapped one.
vec4 materialSample(sampler2D s, mat3 transform, int texCoord) {
    vec2 uv = materialTexCoord(transform, texCoord);
#ifdef STRATA_WRAPPED_MAIN
    vec4 g = strataTexCoordGrad[texCoord == 0 ? 0 : 1];
    mat2 linear = mat2(transform);
    return textureGrad(s, uv, linear * g.xy, linear * g.zw);
#else
    return texture(s, uv);
#endif
}
#endif

#ifdef STRATA_BASE_COLOR_TEXTURE
layout(binding = BIND_BASE_COLOR_TEXTURE) uniform sampler2D uBaseColorTexture;
uniform mat3 uBaseColorTransform;
uniform int uBaseColorTexCoord;
#endif
#ifdef STRATA_METALLIC_ROUGHNESS_TEXTURE
layout(binding = BIND_METALLIC_ROUGHNESS_TEXTURE) uniform sampler2D uMetallicRoughnessTexture;
uniform mat3 uMetallicRoughnessTransform;
uniform int uMetallicRoughnessTexCoord;
#endif
#ifdef STRATA_NORMAL_TEXTURE
layout(binding = BIND_NORMAL_TEXTURE) uniform sampler2D uNormalTexture;
uniform mat3 uNormalTransform;
uniform int uNormalTexCoord;
uniform float uNormalScale;
#endif
#ifdef STRATA_OCCLUSION_TEXTURE
layout(binding = BIND_OCCLUSION_TEXTURE) uniform sampler2D uOcclusionTexture;
uniform mat3 uOcclusionTransform;
uniform int uOcclusionTexCoord;
uniform float uOcclusionStrength;
#endif
#ifdef STRATA_EMISSIVE_TEXTURE
layout(binding = BIND_EMISSIVE_TEXTURE) uniform sampler2D uEmissiveTexture;
uniform mat3 uEmissiveTransform;
uniform int uEmissiveTexCoord;
#endif

vec4 fetchMaterialBaseColor() {
    vec4 texel = vec4(1.0);
    vec4 vertexColor = vec4(1.0);
#ifdef STRATA_BASE_COLOR_TEXTURE
    texel = materialSample(uBaseColorTexture, uBaseColorTransform, uBaseColorTexCoord);
#endif
#ifdef STRATA_VERTEX_COLOR
    vertexColor = vMaterial.color;
#endif
#ifdef STRATA_IMPOSTOR
    texel = strataImpostorAlbedo;  // a stand-in: the texture x COLOR_0 its bake kept
#endif
    return combineBaseColor(vec4(uBaseColor, uAlpha), texel, vertexColor);
}

#ifdef STRATA_ALPHA_MASK
// MASK: common/scene_main.glsl fetches the base colour once, before its discard, and the stage
// reads it from here. A texture fetch after a discard that not every fragment of a quad takes
// has undefined derivatives (GLSL 4.50, 8.9.1), and it would fetch the same texel twice.
vec4 strataMaskBaseColor;
vec4 materialBaseColor() { return strataMaskBaseColor; }
#else
vec4 materialBaseColor() { return fetchMaterialBaseColor(); }
#endif

// Metallic (x) and roughness (y): the factors times the texture's blue and green channels.
vec2 materialMetallicRoughness() {
    vec2 mr = vec2(uMetallic, uRoughness);
#ifdef STRATA_METALLIC_ROUGHNESS_TEXTURE
    vec4 texel = materialSample(uMetallicRoughnessTexture, uMetallicRoughnessTransform, uMetallicRoughnessTexCoord);
    mr *= vec2(texel.b, texel.g);
#endif
    return mr;
}

float materialOcclusion() {
#ifdef STRATA_OCCLUSION_TEXTURE
    return occlusionOf(materialSample(uOcclusionTexture, uOcclusionTransform, uOcclusionTexCoord).r,
                       uOcclusionStrength);
#else
    return 1.0;
#endif
}

vec3 materialEmissive() {
#ifdef STRATA_EMISSIVE_TEXTURE
    return uEmissive * materialSample(uEmissiveTexture, uEmissiveTransform, uEmissiveTexCoord).rgb;
#else
    return uEmissive;
#endif
}

float materialTransmission() {
#ifdef STRATA_TRANSMISSION
    return uTransmission;
#else
    return 0.0;
#endif
}

float materialIor() {
#ifdef STRATA_TRANSMISSION
    return uIor;
#else
    return kDefaultIor;
#endif
}

// The shading normal: `normal` (the interpolated one) bent by the normal texture.
vec3 materialNormal(vec3 normal) {
#ifdef STRATA_NORMAL_TEXTURE
    vec3 texel = materialSample(uNormalTexture, uNormalTransform, uNormalTexCoord).rgb;
    return normalFromMap(normal, vMaterial.tangent, texel, uNormalScale);
#else
    return normal;
#endif
}

#endif
