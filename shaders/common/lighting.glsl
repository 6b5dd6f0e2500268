// The lights a shaded point receives and the eye it is seen from, for every pass that shades
// (common/surface.glsl, the screen-door stages): the shading model of common/shading_model.h
// evaluated at a world position. GpuScene::setFrameUniforms sets them. A scene without lights
// (Strata's default rig) is shaded by the plain build; one with KHR_lights_punctual lights by
// the STRATA_PUNCTUAL_LIGHTS variant, which loops over their block.
#ifndef STRATA_LIGHTING_GLSL
#define STRATA_LIGHTING_GLSL
#include "bindings.h"
#include "shading_model.h"

uniform vec3 uLightDir;  // towards the default light, world space (the key light of other models)
// The eye as a homogeneous point: (position, 1) for a perspective camera, (direction towards
// the eye, 0) for an orthographic one, so one expression gives the direction to it.
uniform vec4 uEye;
#ifdef STRATA_PUNCTUAL_LIGHTS
// The scene's KHR_lights_punctual lights in world space (render/scene_program.hpp's
// kScenePunctualLights variant: only a scene with lights reads this block and loops).
layout(std140, binding = BIND_LIGHTS) uniform Lights {
    PunctualLight uLights[kMaxLights];
};
uniform int uLightCount;
#endif

vec3 directionToEye(vec3 worldPosition) {
    return normalize(uEye.xyz - worldPosition * uEye.w);
}

// A lit material at `worldPosition` with shading normal `normal` (not necessarily unit length):
// the environment term, emission, and each light's reflectedLight, for the diffuse albedo and
// specular F0 of common/shading_model.h's diffuseAlbedo and specularF0.
vec3 shadeLit(vec3 diffuse, vec3 f0, float roughness, float occlusion, vec3 emissive, vec3 normal,
              vec3 worldPosition) {
    vec3 toEye = directionToEye(worldPosition);
    vec3 n = normalFacingEye(normal, toEye);
    vec3 color = environmentAndEmission(diffuse, f0, roughness, occlusion, emissive, n, toEye);
#ifdef STRATA_PUNCTUAL_LIGHTS
    for (int i = 0; i < uLightCount; ++i)
        color += reflectedLight(diffuse, f0, roughness, n, toEye, lightToward(uLights[i], worldPosition),
                                lightIrradianceAt(uLights[i], worldPosition));
#else
    // The default rig (scene/lights.hpp's defaultLight): one directional light.
    color += reflectedLight(diffuse, f0, roughness, n, toEye, uLightDir, vec3(kDefaultLightIrradiance));
#endif
    return color;
}
#endif
