#version 450 core
// Object-space screen-door transparency, hardware version (Sen et al. 4.2): the mask of the
// triangle's alpha level, mapped on the triangle by object_mask.geom.glsl and sampled nearest,
// keeps or rejects the fragment; a kept fragment is written opaque. The geometry stage renames
// the normal (gWorldNormal), so the material uniforms are declared here, not via surface.glsl.
#include "shading.glsl"
#include "alpha_mask.glsl"

uniform vec3 uBaseColor;
uniform float uAlpha;
uniform vec3 uLightDir;

in vec3 gWorldNormal;
in vec2 gMaskCoord;

layout(location = 0) out vec4 outColor;

void main() {
    if (!maskKeeps(ivec2(floor(gMaskCoord)), uAlpha)) discard;
    outColor = vec4(shadeSurface(uBaseColor, gWorldNormal, uLightDir), 1.0);
}
