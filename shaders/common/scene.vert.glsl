#version 450 core
// Transforms a scene mesh; every scene-drawing program shares this vertex stage. A stand-in
// (render/stand_in.hpp: a layered impostor's slice quads) goes through its STRATA_IMPOSTOR
// build, with (u, v, atlas layer, slice) in attribute 2.

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
#ifdef STRATA_IMPOSTOR
layout(location = 2) in vec4 inImpostor;
#endif
// A material's texture coordinates and vertex colour (common/material.glsl), in the builds
// whose material uses them; a mesh without TEXCOORD_1 leaves that attribute disabled (0, 0).
// A mesh without COLOR_0 leaves that attribute disabled too: (0, 0, 0, 1), which GpuScene
// never lets reach a build with STRATA_VERTEX_COLOR. Tangents come with a normal texture.
#include "bindings.h"
#include "material_features.glsl"
#ifdef STRATA_MATERIAL_VARYING
layout(location = ATTRIB_TEXCOORD0) in vec2 inTexCoord0;
layout(location = ATTRIB_TEXCOORD1) in vec2 inTexCoord1;
layout(location = ATTRIB_COLOR) in vec4 inColor;
#ifdef STRATA_NORMAL_TEXTURE
layout(location = ATTRIB_TANGENT) in vec4 inTangent;
#endif
out MaterialVarying {
    vec2 texCoord0;
    vec2 texCoord1;
    vec4 color;
#ifdef STRATA_NORMAL_TEXTURE
    vec4 tangent;
#endif
} vMaterial;
#endif

// The object being drawn (common/object_record.glsl): its record gives the transform and what
// passObjectOn hands the later stages.
#define STRATA_OBJECT_VERTEX_STAGE
#include "object_record.glsl"

uniform mat4 uViewProj;

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
    mat4 model = inModel;
    mat3 normalMatrix = objectNormalMatrix();
    passObjectOn(normalMatrix);
    vWorldNormal = normalMatrix * inNormal;
    vec4 world = model * vec4(inPosition, 1.0);
    vWorldPosition = world.xyz;
#ifdef STRATA_IMPOSTOR
    vImpostor.uv = inImpostor.xy;
    vImpostor.layer = ivec2(inImpostor.zw);
#endif
#ifdef STRATA_MATERIAL_VARYING
    vMaterial.texCoord0 = inTexCoord0;
    vMaterial.texCoord1 = inTexCoord1;
    vMaterial.color = inColor;
#ifdef STRATA_NORMAL_TEXTURE
    // Tangents transform with the surface, as positions do (not by the normal matrix).
    vMaterial.tangent = vec4(mat3(model) * inTangent.xyz, inTangent.w);
#endif
#endif
    gl_Position = uViewProj * world;
}
