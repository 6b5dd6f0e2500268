// A material shaded at a point: every input of common/material.glsl under the lights of
// common/lighting.glsl. For the stages that shade (common/surface.glsl, the screen-door ones).
#ifndef STRATA_SHADE_MATERIAL_GLSL
#define STRATA_SHADE_MATERIAL_GLSL
#include "material.glsl"
#include "lighting.glsl"

// The shaded colour of a material's base colour at a point with the given (interpolated)
// normal: the material's metallic-roughness, transmission and ior, occlusion, emission and
// normal map under the lights (common/lighting.glsl); the base colour itself for an unlit
// material.
vec3 shadeMaterial(vec3 baseColor, vec3 normal, vec3 worldPosition) {
#ifdef STRATA_UNLIT
    return baseColor;
#else
    vec2 metallicRoughness = materialMetallicRoughness();
    float metallic = metallicRoughness.x;
    return shadeLit(diffuseAlbedo(baseColor, metallic, materialTransmission()),
                    specularF0(baseColor, metallic, materialIor()), metallicRoughness.y, materialOcclusion(),
                    materialEmissive(), materialNormal(normal), worldPosition);
#endif
}

#if defined(STRATA_TRANSMISSION) && !defined(STRATA_UNLIT)
// A transmissive material at a point, each input fetched once: its shaded colour, as
// shadeMaterial, and what it lets through per channel (shading_model.h's transmissionFilter)
// times its medium's attenuation where the view ray enters it (the interpolated normal faces the
// eye; KHR_materials_volume's thickness, render/gpu_scene.cpp), for a coverage `coverage`.
SurfaceOptics shadeTransmissive(vec3 baseColor, float coverage, vec3 normal, vec3 worldPosition) {
    vec2 metallicRoughness = materialMetallicRoughness();
    float metallic = metallicRoughness.x;
    vec3 mapped = materialNormal(normal);
    vec3 shaded = shadeLit(diffuseAlbedo(baseColor, metallic, uTransmission), specularF0(baseColor, metallic, uIor),
                           metallicRoughness.y, materialOcclusion(), materialEmissive(), mapped, worldPosition);
    vec3 toEye = directionToEye(worldPosition);
    vec3 through = transmissionFilter(baseColor, metallic, uTransmission, uIor, dot(normalFacingEye(mapped, toEye), toEye));
    if (dot(normal, toEye) > 0.0) through *= uVolumeFilter;
    return surfaceOpticsOf(shaded, coverage, through);
}
#endif

#endif
