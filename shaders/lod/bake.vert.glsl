#version 450 core
// Impostor bake: a mesh in object space seen from one view's apex (lod/impostor_frame.hpp).
// t, the distance from the apex normalised over the slab, is linear in the position, so the
// vertex stage computes it and perspective-correct interpolation keeps it exact.

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;

uniform mat4 uViewProj;   // object space -> the view's back-perspective clip space
uniform vec3 uApex;
uniform vec3 uAxis;
uniform float uSlabNear;  // D - r
uniform float uSlabDepth; // 2 r

out vec3 vObjectNormal;
out float vSlabT;

void main() {
    vObjectNormal = inNormal;
    vSlabT = (dot(inPosition - uApex, uAxis) - uSlabNear) / uSlabDepth;
    gl_Position = uViewProj * vec4(inPosition, 1.0);
}
