#version 450 core
// Transforms a scene mesh; every scene-drawing program shares this vertex stage.

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;

uniform mat4 uViewProj;
uniform mat4 uModel;
uniform mat3 uNormalMatrix;

out vec3 vWorldNormal;

void main() {
    vWorldNormal = uNormalMatrix * inNormal;
    gl_Position = uViewProj * (uModel * vec4(inPosition, 1.0));
}
