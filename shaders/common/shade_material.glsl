// A material shaded at a point: every input of common/material.glsl under the lights of
// common/lighting.glsl. For the stages that shade (common/surface.glsl, the screen-door ones).
#ifndef STRATA_SHADE_MATERIAL_GLSL
#define STRATA_SHADE_MATERIAL_GLSL
#include "material.glsl"
#include "lighting.glsl"

// The shaded colour of a material's base colour at a point with the given (interpolated)
// normal: the material's metallic-roughness, occlusion, emission and normal map under the
// lights (common/lighting.glsl); the base colour itself for an unlit material.
vec3 shadeMaterial(vec3 baseColor, vec3 normal, vec3 worldPosition) {
#ifdef STRATA_UNLIT
    return baseColor;
#else
    vec2 metallicRoughness = materialMetallicRoughness();
    return shadeLit(baseColor, metallicRoughness.x, metallicRoughness.y, materialOcclusion(), materialEmissive(),
                    materialNormal(normal), worldPosition);
#endif
}

#endif
