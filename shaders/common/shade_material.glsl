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

#ifdef STRATA_TRANSMISSION
// What a transmissive material lets through at a point, per channel (shading_model.h's
// transmissionFilter), times its medium's attenuation where the view ray enters it (the
// interpolated normal faces the eye): KHR_materials_volume's thickness, render/gpu_scene.cpp.
vec3 materialTransmitted(vec3 baseColor, vec3 normal, vec3 worldPosition) {
    vec3 toEye = directionToEye(worldPosition);
    vec3 n = normalFacingEye(materialNormal(normal), toEye);
    vec3 through = transmissionFilter(baseColor, materialMetallicRoughness().x, uTransmission, uIor, dot(n, toEye));
    return dot(normal, toEye) > 0.0 ? through * uVolumeFilter : through;
}
#endif

#endif
