#version 450 core
// Draws the kept point samples of screendoor-object-sw (one-sample points, pulled from their
// buffer by vertex id); the fragment stage writes them opaque with the z-buffer on.
#include "screendoor_bindings.h"

layout(std430, binding = BIND_POINTS) readonly buffer Points { ScreenDoorPoint points[]; };

uniform mat4 uViewProj;

out vec3 vPointNormal;
out vec3 vPointPosition;
flat out uint vObjectId;
flat out vec3 vTint;

void main() {
    ScreenDoorPoint p = points[gl_VertexID];
    gl_Position = uViewProj * vec4(p.x, p.y, p.z, 1.0);
    vPointNormal = unpackSnorm4x8(p.normal).xyz;
    vPointPosition = vec3(p.x, p.y, p.z);
    vObjectId = p.object;
    vTint = vec3(unpackHalf2x16(p.tintRG), unpackHalf2x16(p.tintB).x);
}
