#version 450 core
// Impostor bake: a mesh (one part of a unit, placed by uModel) seen from one view's apex
// (lod/impostor_frame.hpp).
// t, the distance from the apex normalised over the slab, is linear in the position, so the
// vertex stage computes it and perspective-correct interpolation keeps it exact.
// BAKE_ALBEDO: the material's texture coordinates and COLOR_0 go on to the fragment stage
// (the mesh's vertex array holds them at common/bindings.h's locations where it has them; the
// uniforms say which it has, since an absent attribute reads GL's current value).
#include "common/bindings.h"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;

uniform mat4 uModel;         // the part's space -> the impostor's (identity for a single mesh)
uniform mat3 uNormalMatrix;  // its inverse transpose
uniform mat4 uViewProj;   // the impostor's space -> the view's back-perspective clip space
uniform vec3 uApex;
uniform vec3 uAxis;
uniform float uSlabNear;  // D - r
uniform float uSlabDepth; // 2 r

out vec3 vObjectNormal;
out float vSlabT;

#ifdef BAKE_ALBEDO
layout(location = ATTRIB_TEXCOORD0) in vec2 inTexCoord0;
layout(location = ATTRIB_TEXCOORD1) in vec2 inTexCoord1;
layout(location = ATTRIB_COLOR) in vec4 inColor;
uniform int uBaseColorTexCoord;  // the TEXCOORD set of the base colour texture
uniform bool uVertexColor;       // the mesh has COLOR_0 and the material uses it
out vec2 vTexCoord;
out vec4 vColor;
#endif

void main() {
    vec3 position = (uModel * vec4(inPosition, 1.0)).xyz;
    vObjectNormal = uNormalMatrix * inNormal;
    vSlabT = (dot(position - uApex, uAxis) - uSlabNear) / uSlabDepth;
    gl_Position = uViewProj * vec4(position, 1.0);
#ifdef BAKE_ALBEDO
    vTexCoord = uBaseColorTexCoord == 0 ? inTexCoord0 : inTexCoord1;
    vColor = uVertexColor ? inColor : vec4(1.0);
#endif
}
