#version 450 core
// An object's world-space bounding box from the unit cube's corners.
layout(location = 0) in vec3 inCorner;
uniform mat4 uViewProj;
uniform vec3 uBoxMin;
uniform vec3 uBoxMax;

void main() {
    gl_Position = uViewProj * vec4(mix(uBoxMin, uBoxMax, inCorner), 1.0);
}
