#version 450 core
// A kept point sample, shaded with its object's colour and written opaque. The samples carry
// no texture coordinates or material but the colour: each is shaded as a rough dielectric of
// its object's factor colour times its tint (the base colour texture and COLOR_0 where the
// point was sampled; modes lists this technique as approximate), or left as that colour for an
// unlit material.
#include "lighting.glsl"
#include "screendoor_bindings.h"

layout(std430, binding = BIND_OBJECT_COLORS) readonly buffer ObjectColors { vec4 objectColors[]; };  // by object id

in vec3 vPointNormal;
in vec3 vPointPosition;
flat in uint vObjectId;
flat in vec3 vTint;

layout(location = 0) out vec4 outColor;

void main() {
    vec4 color = objectColors[vObjectId];  // alpha 0: unlit (core/oit/screendoor/point_samples.cpp)
    color.rgb *= vTint;
    outColor = vec4(color.a == 0.0 ? color.rgb
                                   : shadeLit(color.rgb, vec3(kDielectricF0), 1.0, 1.0, vec3(0.0), vPointNormal, vPointPosition), 1.0);
}
