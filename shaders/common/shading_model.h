// The shading and material model, written once for the CPU reference (C++, through
// core/render/shading.hpp) and every GPU pass (GLSL, through common/shading.glsl), so the
// reference cannot drift from the GPU. Valid C++ and GLSL at once (common/host_device.h): GLSL
// names (vec3, dot, abs) are glm's in C++, and functions are `GPU_FN`.
#ifndef STRATA_SHADING_MODEL_H
#define STRATA_SHADING_MODEL_H
#include "common/host_device.h"

#ifdef __cplusplus
#include <glm/glm.hpp>
#define GPU_FN inline
namespace strata::gpu {
using glm::abs;
using glm::cross;
using glm::dot;
using glm::exp2;
using glm::length;
using glm::max;
using glm::min;
using glm::mix;
using glm::pow;
using glm::sqrt;
using glm::vec2;
using glm::vec3;
using glm::vec4;
using glm::mat3;
}  // namespace strata::gpu
#else
#define GPU_FN
#endif

GPU_NAMESPACE_BEGIN

// The lighting: a uniform environment of radiance kAmbient (so a white Lambert surface in it
// alone reflects kAmbient, as Strata's shading always had) plus lights. Strata's default rig is
// one directional light (Scene::lightDirection) whose irradiance makes a white rough dielectric
// facing it reach about 1: kDefaultLightIrradiance.
GPU_CONST float kAmbient = 0.3f;
GPU_CONST float kPi = 3.14159265358979f;
GPU_CONST float kDefaultLightIrradiance = (1.0f - kAmbient) * kPi;
// Roughness below this is taken as this: a mirror's highlight (alpha -> 0) makes D(alpha) grow
// as 1 / alpha^2 without bound; at 0.089 (Filament's floor for half-float targets) a metal's
// highlight under the default light stays below 2e4, far inside fp16's 65504, so an fp16 layer
// store cannot overflow to infinity.
GPU_CONST float kMinRoughness = 0.089f;
// Dielectric reflectance at normal incidence: an index of refraction of 1.5 (glTF appendix B).
GPU_CONST float kDielectricF0 = 0.04f;
GPU_CONST float kDefaultIor = 1.5f;

// KHR_materials_ior: a dielectric's reflectance at normal incidence, ((ior - 1) / (ior + 1))^2
// (kDielectricF0 at the default 1.5; 0 at ior 1, where nothing is reflected).
GPU_FN float dielectricF0(float ior) {
    float r = (ior - 1.0f) / (ior + 1.0f);
    return r * r;
}

// The two colours appendix B's BRDF mixes, from the material's parameters: the diffuse albedo
// c_diff = base (1 - metallic), less the fraction `transmission` of the dielectric base that
// lets light through instead of scattering it (KHR_materials_transmission), and the specular
// F0 = mix(dielectric F0 from the ior, base, metallic).
GPU_FN vec3 diffuseAlbedo(vec3 baseColor, float metallic, float transmission) {
    return baseColor * ((1.0f - metallic) * (1.0f - transmission));
}
GPU_FN vec3 specularF0(vec3 baseColor, float metallic, float ior) {
    return mix(vec3(dielectricF0(ior)), baseColor, metallic);
}

// glTF 2.0 appendix B, the metallic-roughness BRDF, with alpha = roughness^2.
// Trowbridge-Reitz (GGX) distribution D, for n.h > 0.
GPU_FN float ggxDistribution(float alpha, float nDotH) {
    float a2 = alpha * alpha;
    float d = nDotH * nDotH * (a2 - 1.0f) + 1.0f;
    return a2 / (kPi * d * d);
}

// Smith's separable masking-shadowing G = G1(l) G1(v) folded with the BRDF's
// 1 / (4 |n.l| |n.v|): V = G / (4 |n.l| |n.v|), the appendix's form.
GPU_FN float smithVisibility(float alpha, float nDotL, float nDotV) {
    float a2 = alpha * alpha;
    float l = nDotL + sqrt(a2 + (1.0f - a2) * nDotL * nDotL);
    float v = nDotV + sqrt(a2 + (1.0f - a2) * nDotV * nDotV);
    return 1.0f / (l * v);
}

GPU_FN vec3 schlickFresnel(vec3 f0, float vDotH) {
    float m = 1.0f - vDotH;
    float m2 = m * m;
    return f0 + (vec3(1.0f) - f0) * (m2 * m2 * m);
}

// The normal a shading point uses: the surface's, turned to face the eye (a back face seen
// through a transparent front is shaded as the side the eye sees); a degenerate normal (zero
// length) faces the eye.
GPU_FN vec3 normalFacingEye(vec3 normal, vec3 toEye) {
    float len = length(normal);
    if (!(len > 0.0f)) return toEye;
    vec3 n = normal / len;
    return dot(n, toEye) < 0.0f ? -n : n;
}

// Radiance reflected towards `toEye` from a light arriving from `toLight` with `irradiance` (on
// a surface facing it): (f_diffuse + f_specular) E (n.l), with
//   F = Schlick(F0, v.h), f_diffuse = (1 - F) c_diff / pi,  f_specular = F D V,
// with c_diff and F0 from diffuseAlbedo and specularF0.
// All directions are unit vectors; `n` faces the eye.
GPU_FN vec3 reflectedLight(vec3 diffuse, vec3 f0, float roughness, vec3 n, vec3 toEye, vec3 toLight,
                           vec3 irradiance) {
    float nDotL = dot(n, toLight);
    if (!(nDotL > 0.0f)) return vec3(0.0f);
    float nDotV = max(dot(n, toEye), 1e-4f);
    // toLight + toEye is zero only for a light straight behind the point seen, which n.l > 0 and
    // n.v >= 0 exclude but for grazing round-off; then the half vector is the normal.
    vec3 sum = toLight + toEye;
    float sumLength = length(sum);
    vec3 h = sumLength > 1e-6f ? sum / sumLength : n;
    float r = max(roughness, kMinRoughness);
    float alpha = r * r;
    vec3 f = schlickFresnel(f0, max(dot(toEye, h), 0.0f));
    vec3 diffuseLobe = (vec3(1.0f) - f) * diffuse / kPi;
    vec3 specular = f * (ggxDistribution(alpha, max(dot(n, h), 0.0f)) * smithVisibility(alpha, nDotL, nDotV));
    return (diffuseLobe + specular) * irradiance * nDotL;
}

// What the uniform environment reflects: the diffuse colour times the environment radiance,
// plus the specular lobe's directional albedo for F0, approximated analytically (Karis's fit to
// the split-sum table, "Physically Based Shading on Mobile", 2014; within 0.16 of the integral
// of this BRDF's lobe, tests/shading_model_test.cpp); both scaled by the
// material's ambient occlusion, which glTF applies to indirect light only.
GPU_FN vec3 environmentLight(vec3 diffuse, vec3 f0, float roughness, float occlusion, float nDotV) {
    float r = max(roughness, kMinRoughness);
    vec4 c = vec4(-1.0f, -0.0275f, -0.572f, 0.022f) * r + vec4(1.0f, 0.0425f, 1.04f, -0.04f);
    float a004 = min(c.x * c.x, exp2(-9.28f * nDotV)) * c.x + c.y;
    vec2 ab = vec2(-1.04f, 1.04f) * a004 + vec2(c.z, c.w);
    vec3 specularAlbedo = f0 * ab.x + vec3(ab.y);
    return (diffuse + specularAlbedo) * (kAmbient * occlusion);
}

// A light as every shading pass and the CPU reference receive it, in world space: a file's
// KHR_lights_punctual lights placed by their nodes, or Strata's default rig (one directional
// light along Scene::lightDirection of irradiance kDefaultLightIrradiance). vec4s only, so the
// C++ struct and GLSL's std140 block lay it out alike.
GPU_CONST int kLightDirectional = 0;
GPU_CONST int kLightPoint = 1;
GPU_CONST int kLightSpot = 2;
GPU_CONST int kMaxLights = 64;  // per scene; the loader says what it drops past this
struct PunctualLight {
    vec4 colorType;      // rgb: colour x intensity (lux, or candela for point and spot); w: kLight*
    vec4 positionRange;  // xyz: position; w: range (0: unlimited)
    vec4 directionCone;  // xyz: unit direction the light shines along; w: spot's 1 / (cos inner - cos outer)
    vec4 coneOffset;     // x: spot's -cos(outer) / (cos inner - cos outer)
};

// The unit direction from `position` towards the light.
GPU_FN vec3 lightToward(PunctualLight light, vec3 position) {
    vec3 along = vec3(light.directionCone.x, light.directionCone.y, light.directionCone.z);
    if (int(light.colorType.w) == kLightDirectional) return -along;
    vec3 d = vec3(light.positionRange.x, light.positionRange.y, light.positionRange.z) - position;
    float len = length(d);
    return len > 0.0f ? d / len : -along;
}

// What the light delivers at `position` on a surface facing it (KHR_lights_punctual): a
// directional light its intensity; a point light intensity / d^2, windowed by the range as the
// extension recommends, clamp(1 - (d / range)^4, 0, 1); a spot light that times the smoothed
// cone, clamp(cos(angle) * scale + offset, 0, 1)^2.
GPU_FN vec3 lightIrradianceAt(PunctualLight light, vec3 position) {
    vec3 color = vec3(light.colorType.x, light.colorType.y, light.colorType.z);
    int type = int(light.colorType.w);
    if (type == kLightDirectional) return color;
    vec3 d = vec3(light.positionRange.x, light.positionRange.y, light.positionRange.z) - position;
    float d2 = max(dot(d, d), 1e-8f);
    float range = light.positionRange.w;
    float window = 1.0f;
    if (range > 0.0f) {
        float r = d2 / (range * range);
        window = min(max(1.0f - r * r, 0.0f), 1.0f);
    }
    float attenuation = window / d2;
    if (type == kLightSpot) {
        vec3 along = vec3(light.directionCone.x, light.directionCone.y, light.directionCone.z);
        float cosAngle = dot(along, -d / sqrt(d2));
        float cone = min(max(cosAngle * light.directionCone.w + light.coneOffset.x, 0.0f), 1.0f);
        attenuation *= cone * cone;
    }
    return color * attenuation;
}

// What a lit material shows before its lights: the environment term and its emission. `n` is
// the normal facing the eye (normalFacingEye). Each light adds its reflectedLight to this.
GPU_FN vec3 environmentAndEmission(vec3 diffuse, vec3 f0, float roughness, float occlusion, vec3 emissive, vec3 n,
                                   vec3 toEye) {
    return environmentLight(diffuse, f0, roughness, occlusion, max(dot(n, toEye), 0.0f)) + emissive;
}

// The shaded colour of a lit material under the environment and one light (a scene's further
// lights add their reflectedLight terms: common/lighting.glsl, the CPU reference).
// `emissive` is emissiveFactor x texture x emissive strength.
GPU_FN vec3 shadeSurface(vec3 baseColor, float metallic, float roughness, float occlusion, vec3 emissive,
                         vec3 normal, vec3 toEye, vec3 toLight, vec3 lightIrradiance) {
    vec3 n = normalFacingEye(normal, toEye);
    vec3 diffuse = diffuseAlbedo(baseColor, metallic, 0.0f);
    vec3 f0 = specularF0(baseColor, metallic, kDefaultIor);
    return environmentAndEmission(diffuse, f0, roughness, occlusion, emissive, n, toEye) +
           reflectedLight(diffuse, f0, roughness, n, toEye, toLight, lightIrradiance);
}

// KHR_materials_transmission without refraction (the transmitted ray goes on straight): what a
// transmissive surface lets through, per channel. The transmitted fraction of the dielectric
// base, tinted by the base colour, less what its specular layer reflects at this view angle
// (Schlick's Fresnel for the ior). `nDotV` is the cosine between the normal facing the eye and
// the direction to the eye.
GPU_FN vec3 transmissionFilter(vec3 baseColor, float metallic, float transmission, float ior, float nDotV) {
    float f0 = dielectricF0(ior);
    float m = 1.0f - min(max(nDotV, 0.0f), 1.0f);
    float m2 = m * m;
    float fresnel = f0 + (1.0f - f0) * (m2 * m2 * m);
    return baseColor * (transmission * (1.0f - metallic) * (1.0f - fresnel));
}

// One transparent fragment's effect on what lies behind it, C = premultiplied + transmittance *
// C_behind: a coverage `alpha` of a surface that shades `shaded` and lets `transmitted` through
// (transmissionFilter; zero for a surface that transmits nothing, which gives the usual
// (alpha c, 1 - alpha)). ("filter" is a reserved word in GLSL.)
struct SurfaceOptics {
    vec3 premultiplied;
    vec3 transmittance;
};
GPU_FN SurfaceOptics surfaceOpticsOf(vec3 shaded, float alpha, vec3 transmitted) {
    SurfaceOptics o;
    o.premultiplied = shaded * alpha;
    o.transmittance = vec3(1.0f - alpha) + transmitted * alpha;
    return o;
}

// The same fragment as one colour and one alpha, for the techniques that composite a scalar
// transmittance (the approximate ones, peeling): alpha = 1 - mean(transmittance), colour the
// premultiplied colour over it, so that alpha * colour is exact and only the filter's tint
// is lost. Where almost nothing is absorbed but light is reflected (clear glass: a highlight on
// a filter of ~1) the alpha is held at kMinScalarAlpha, and the colour at most
// 1 / kMinScalarAlpha times the light; where nothing is reflected either (a coverage-0 texel)
// the fragment is (0, alpha): it lets everything through.
GPU_CONST float kMinScalarAlpha = 1.0f / 256.0f;
GPU_FN vec4 scalarOpacityForm(SurfaceOptics o) {
    float alpha = min(max(1.0f - (o.transmittance.x + o.transmittance.y + o.transmittance.z) / 3.0f, 0.0f), 1.0f);
    if (alpha < kMinScalarAlpha) {
        if (!(max(o.premultiplied.x, max(o.premultiplied.y, o.premultiplied.z)) > 0.0f))
            return vec4(0.0f, 0.0f, 0.0f, alpha);
        alpha = kMinScalarAlpha;
    }
    return vec4(o.premultiplied / alpha, alpha);
}

// The sRGB transfer function's inverse (glTF colour textures; the GL specification's decode for
// SRGB8_ALPHA8 texels, which the GPU applies per texel before filtering).
GPU_FN float srgbToLinear(float c) {
    return c <= 0.04045f ? c / 12.92f : pow((c + 0.055f) / 1.055f, 2.4f);
}

// KHR_texture_transform applied to a TEXCOORD (the matrix is TextureTransform::matrix()).
GPU_FN vec2 transformTexCoord(mat3 transform, vec2 uv) {
    vec3 t = transform * vec3(uv.x, uv.y, 1.0f);
    return vec2(t.x, t.y);
}

// glTF's base colour: factor x texture texel (linear) x COLOR_0, alpha likewise. A material
// without a texture passes (1, 1, 1, 1) for the texel, a mesh without COLOR_0 the same for the
// colour, so the product is the factor alone.
GPU_FN vec4 combineBaseColor(vec4 factor, vec4 texel, vec4 vertexColor) {
    return factor * texel * vertexColor;
}

// The occlusion texture's red channel, mixed in by the material's strength (glTF 3.9.3).
GPU_FN float occlusionOf(float texelRed, float strength) {
    return 1.0f + strength * (texelRed - 1.0f);
}

// A normal texture's texel (linear, in [0, 1]) as a direction in the frame of the interpolated
// normal and tangent (glTF 3.9.3): m = (2 texel - 1) scaled by `scale` in x and y, taken along
// the tangent, the bitangent cross(n, t) * w and the normal. The tangent is made orthogonal to
// the normal first (interpolation bends them apart); a tangent along the normal, or a zero
// normal, leaves the normal as it was.
GPU_FN vec3 normalFromMap(vec3 normal, vec4 tangent, vec3 texel, float scale) {
    float len = length(normal);
    if (!(len > 0.0f)) return normal;
    vec3 n = normal / len;
    vec3 t = vec3(tangent.x, tangent.y, tangent.z);
    t = t - n * dot(n, t);
    float tLen = length(t);
    if (!(tLen > 1e-12f)) return n;
    t = t / tLen;
    vec3 b = cross(n, t) * (tangent.w < 0.0f ? -1.0f : 1.0f);
    vec3 m = (texel * 2.0f - vec3(1.0f)) * vec3(scale, scale, 1.0f);
    vec3 mapped = t * m.x + b * m.y + n * m.z;
    float mappedLen = length(mapped);
    return mappedLen > 0.0f ? mapped / mappedLen : n;
}

// MASK: the fragment exists where alpha >= alphaCutoff (glTF 2.0, 3.9.4).
GPU_FN bool alphaMaskKeeps(float alpha, float cutoff) {
    return alpha >= cutoff;
}

GPU_NAMESPACE_END

#endif
