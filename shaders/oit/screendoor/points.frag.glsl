#version 450 core
// A kept point sample, shaded with its object's colour and written opaque.
#include "shading.glsl"
#include "screendoor_bindings.h"

layout(std430, binding = BIND_OBJECT_COLORS) readonly buffer ObjectColors { vec4 objectColors[]; };  // by object id

uniform vec3 uLightDir;

in vec3 vPointNormal;
flat in uint vObjectId;

layout(location = 0) out vec4 outColor;

void main() {
    outColor = vec4(shadeSurface(objectColors[vObjectId].rgb, vPointNormal, uLightDir), 1.0);
}
