// The light a shaded point receives and the eye it is seen from, for every pass that shades
// (common/surface.glsl, the screen-door stages): the shading model of common/shading_model.h
// evaluated at a world position. GpuScene::setFrameUniforms sets both uniforms.
#ifndef STRATA_LIGHTING_GLSL
#define STRATA_LIGHTING_GLSL
#include "shading_model.h"

uniform vec3 uLightDir;  // towards the default light, world space
// The eye as a homogeneous point: (position, 1) for a perspective camera, (direction towards
// the eye, 0) for an orthographic one, so one expression gives the direction to it.
uniform vec4 uEye;

vec3 directionToEye(vec3 worldPosition) {
    return normalize(uEye.xyz - worldPosition * uEye.w);
}

// A lit material at `worldPosition` with shading normal `normal` (not necessarily unit length).
vec3 shadeLit(vec3 baseColor, float metallic, float roughness, float occlusion, vec3 emissive, vec3 normal,
              vec3 worldPosition) {
    return shadeSurface(baseColor, metallic, roughness, occlusion, emissive, normal, directionToEye(worldPosition),
                        uLightDir, vec3(kDefaultLightIrradiance));
}
#endif
