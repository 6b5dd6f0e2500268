#version 450 core
// Transforms a scene mesh; every scene-drawing program shares this vertex stage.

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;

uniform mat4 uViewProj;
uniform mat4 uModel;
uniform mat3 uNormalMatrix;

out vec3 vWorldNormal;
// World position: a geometry stage (oit/screendoor/object_mask.geom.glsl) measures triangles
// with it and crow's fragment stage takes the view direction from it; unused stages drop it.
out vec3 vWorldPosition;

void main() {
    vWorldNormal = uNormalMatrix * inNormal;
    vec4 world = uModel * vec4(inPosition, 1.0);
    vWorldPosition = world.xyz;
    gl_Position = uViewProj * world;
}
