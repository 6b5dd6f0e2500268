#version 450 core
// Object-space mask coordinates (Sen et al. 4.2.1): each triangle gets texture coordinates, in
// mask texels, such that one texel covers about one supersampled pixel when the triangle is
// turned parallel to the image plane at the distance d of its centroid. With U = P1 - P0,
// V = P2 - P0 scaled by s = N h_im / (d h) = h_im / (2 d tan(fov / 2)) samples per scene unit:
//   C0 = (0, 0),  C1 = (|U_t|, 0),  C2 = (k, sqrt(|V_t|^2 - k^2)),  k = U_t . V_t / |U_t|,
// an isometric unfolding of the triangle, so the mask is laid on the surface (object space),
// not on the image. A random texel offset per triangle keeps neighbouring and overlapping
// triangles of one alpha from reusing the same texels.
// d is the centroid's depth along the view axis, not its Euclidean distance: the projection
// divides by that depth, and at wide angles the two differ (by 10x at 84 degrees off-axis), which
// would make texels cover many samples and clump the kept ones.
#include "alpha_mask.glsl"

layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

in vec3 vWorldNormal[];
in vec3 vWorldPosition[];

uniform vec3 uEyePosition;
uniform vec3 uViewAxis;         // unit vector the camera looks along
uniform float uSamplesPerUnit;  // supersampled pixels per scene unit at distance 1

// The object being drawn (common/object_record.glsl), passed on to the fragment stage.
#define STRATA_OBJECT_GEOMETRY_STAGE
#include "common/object_record.glsl"
in ObjectVarying { STRATA_OBJECT_VARYING_MEMBERS } objectIn[];
out ObjectVarying { STRATA_OBJECT_VARYING_MEMBERS } objectOut;
#define uObjectId (objectIn[0].id)

#ifdef STRATA_IMPOSTOR
// Passed on to the scene fragment wrapper (common/scene_main.glsl) under the same block name.
in ImpostorVarying {
    vec2 uv;
    flat ivec2 layer;
} impostorIn[];
out ImpostorVarying {
    vec2 uv;
    flat ivec2 layer;
} impostorOut;
#endif

#include "material_features.glsl"
#ifdef STRATA_MATERIAL_VARYING
// Passed on to common/material.glsl under the same block name.
in MaterialVarying {
    vec2 texCoord0;
    vec2 texCoord1;
    vec4 color;
#ifdef STRATA_NORMAL_TEXTURE
    vec4 tangent;
#endif
} materialIn[];
out MaterialVarying {
    vec2 texCoord0;
    vec2 texCoord1;
    vec4 color;
#ifdef STRATA_NORMAL_TEXTURE
    vec4 tangent;
#endif
} materialOut;
#endif

out vec3 gWorldNormal;
out vec3 gWorldPosition;
out vec2 gMaskCoord;  // mask texels

void main() {
    vec3 u = vWorldPosition[1] - vWorldPosition[0];
    vec3 v = vWorldPosition[2] - vWorldPosition[0];
    vec3 middle = (vWorldPosition[0] + vWorldPosition[1] + vWorldPosition[2]) / 3.0;
    float scale = uSamplesPerUnit / max(dot(middle - uEyePosition, uViewAxis), 1e-20);
    float lu = length(u) * scale;
    float lv = length(v) * scale;
    float k = lu > 0.0 ? dot(u, v) * scale * scale / lu : 0.0;
    vec2 offset = vec2(maskOffset(uObjectId, uint(gl_PrimitiveIDIn)));
    vec2 coords[3] = vec2[3](vec2(0.0), vec2(lu, 0.0), vec2(k, sqrt(max(lv * lv - k * k, 0.0))));
    for (int i = 0; i < 3; ++i) {
        gl_Position = gl_in[i].gl_Position;
        objectOut.id = objectIn[i].id;
        objectOut.volumeEntry = objectIn[i].volumeEntry;
        objectOut.volumeFilter = objectIn[i].volumeFilter;
#ifdef STRATA_IMPOSTOR
        objectOut.normalMatrix = objectIn[i].normalMatrix;
#endif
        gWorldNormal = vWorldNormal[i];
        gWorldPosition = vWorldPosition[i];
#ifdef STRATA_IMPOSTOR
        impostorOut.uv = impostorIn[i].uv;
        impostorOut.layer = impostorIn[i].layer;
#endif
#ifdef STRATA_MATERIAL_VARYING
        materialOut.texCoord0 = materialIn[i].texCoord0;
        materialOut.texCoord1 = materialIn[i].texCoord1;
        materialOut.color = materialIn[i].color;
#ifdef STRATA_NORMAL_TEXTURE
        materialOut.tangent = materialIn[i].tangent;
#endif
#endif
        gMaskCoord = offset + coords[i];
        EmitVertex();
    }
    EndPrimitive();
}
