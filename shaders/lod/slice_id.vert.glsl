#version 450 core
// Hole-filling preprocessing (Schaufler 3.3): impostor slice quads drawn with ids.

layout(location = 0) in vec3 inPosition;   // object space
layout(location = 2) in vec4 inSlice;      // u, v, atlas layer, slice

uniform mat4 uViewProj;

out vec2 vUv;
flat out int vLayer;
flat out int vSlice;

void main() {
    vUv = inSlice.xy;
    vLayer = int(inSlice.z + 0.5);
    vSlice = int(inSlice.w + 0.5);
    gl_Position = uViewProj * vec4(inPosition, 1.0);
}
