#version 450 core
// Transforms a scene mesh; every scene-drawing program shares this vertex stage. A stand-in
// (render/stand_in.hpp: a layered impostor's slice quads) goes through its STRATA_IMPOSTOR
// build, with (u, v, atlas layer, slice) in attribute 2.

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
#ifdef STRATA_IMPOSTOR
layout(location = 2) in vec4 inImpostor;
#endif

uniform mat4 uViewProj;
uniform mat4 uModel;
uniform mat3 uNormalMatrix;

out vec3 vWorldNormal;
// World position: a geometry stage (oit/screendoor/object_mask.geom.glsl) measures triangles
// with it and crow's fragment stage takes the view direction from it; unused stages drop it.
out vec3 vWorldPosition;
#ifdef STRATA_IMPOSTOR
// Read by the scene fragment wrapper (common/scene_main.glsl); a block, so a geometry stage
// can pass it on under the same block name.
out ImpostorVarying {
    vec2 uv;
    flat ivec2 layer;  // atlas layer, slice
} vImpostor;
#endif

void main() {
    vWorldNormal = uNormalMatrix * inNormal;
    vec4 world = uModel * vec4(inPosition, 1.0);
    vWorldPosition = world.xyz;
#ifdef STRATA_IMPOSTOR
    vImpostor.uv = inImpostor.xy;
    vImpostor.layer = ivec2(inImpostor.zw);
#endif
    gl_Position = uViewProj * world;
}
