// Per-object material uniforms and the shaded colour of the current fragment.
#include "bindings.h"
#include "shading.glsl"

uniform vec3 uBaseColor;
uniform float uAlpha;
uniform uint uObjectId;
uniform vec3 uLightDir;
uniform float uAlphaCutoff;

in vec3 vWorldNormal;

vec4 surfaceColor() {
    return vec4(shadeSurface(uBaseColor, vWorldNormal, uLightDir), uAlpha);
}
