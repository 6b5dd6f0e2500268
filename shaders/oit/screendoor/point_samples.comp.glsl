#version 450 core
// Object-space point sampling (Sen et al. 4.1): one triangle per invocation column lays a lattice
// of n = (N h_im / (d h))^2 A points on the triangle, that is one point per supersampled pixel
// when the triangle is turned parallel to the image plane at its centroid's view depth d
// (4.1.1), uniform in the plane's (u, v) coordinates, and keeps each with probability alpha from
// its own random number (4.1.2). Kept points are appended for the point pass. The lattice is fixed
// on the surface's density (object space), so where the surface turns away from the eye more
// points fall in each pixel and the silhouette grows opaque.
//
// The lattice's axes in the triangle's plane follow the camera's right vector, and its origin and
// phase are the object's (world origin, a random phase per object): coplanar neighbours at one
// depth share one lattice, so a face-on surface gets exactly one point per sample (no seams,
// coverage alpha), which a lattice laid along each triangle's own first edge does not.
//
// The probability a point is kept is the material's alpha there: the factor's keep probability
// (core/oit/screendoor/point_samples.cpp) times the base colour texture's alpha and COLOR_0's at
// the point, the texture read at the level of the lattice's spacing (textureGrad); MASK keeps
// where that alpha reaches the cutoff, with the factor's probability. The point carries the
// texture's and COLOR_0's colour, which the point pass multiplies into the factor colour.
//
// Bounds: d is at least the near plane; a triangle wanting more than uMaxTriangleSamples points
// gets a coarser lattice of that many and is counted; points past uCapacity are counted, not
// written (the host grows the buffer and samples again).
#include "bindings.h"
#include "screendoor_bindings.h"
#include "random_hash.glsl"
#include "common/shading_model.h"

layout(local_size_x = POINT_SAMPLES_GROUP_SIZE) in;

layout(std430, binding = BIND_MESH_VERTICES) readonly buffer MeshVertices { float vertices[]; };  // position, normal
layout(std430, binding = BIND_MESH_INDICES) readonly buffer MeshIndices { uint indices[]; };
layout(std430, binding = BIND_POINTS) writeonly buffer Points { ScreenDoorPoint points[]; };
layout(binding = BIND_COUNTERS, offset = 0) uniform atomic_uint uPointsWanted;
layout(binding = BIND_COUNTERS, offset = 4) uniform atomic_uint uTrianglesBounded;

uniform mat4 uModel;
uniform mat3 uNormalMatrix;
uniform uint uTriangleCount;
uniform uint uObjectId;
uniform float uAlpha;
uniform uint uSeed;
uniform vec3 uEyePosition;
uniform vec3 uViewAxis;
uniform vec3 uViewRight;
uniform float uSamplesPerUnit;  // supersampled pixels per scene unit at depth 1
uniform float uNearPlane;
uniform float uMaxTriangleSamples;
uniform uint uCapacity;
uniform uint uChunks;            // invocations along y per triangle

// The material's detail, where it has any (else uTextured false and the offsets -1).
layout(std430, binding = BIND_MESH_ATTRIBUTES) readonly buffer MeshAttributes { float attributes[]; };
layout(binding = BIND_BASE_COLOR_TEXTURE) uniform sampler2D uBaseColorTexture;
uniform bool uTextured;
uniform mat3 uBaseColorTransform;  // KHR_texture_transform
uniform int uTexCoordOffset;       // floats into attributes of the texture's TEXCOORD array
uniform int uColorOffset;          // floats into attributes of COLOR_0, -1 without
uniform float uFactorAlpha;        // the factor alpha (MASK compares alpha with the cutoff)
uniform float uAlphaCutoff;        // MASK's, 0 otherwise

vec2 texCoordOf(uint v) { return vec2(attributes[uTexCoordOffset + 2 * int(v)], attributes[uTexCoordOffset + 2 * int(v) + 1]); }
vec4 colorOf(uint v) {
    int i = uColorOffset + 4 * int(v);
    return vec4(attributes[i], attributes[i + 1], attributes[i + 2], attributes[i + 3]);
}

vec3 position(uint v) { return (uModel * vec4(vertices[6 * v], vertices[6 * v + 1], vertices[6 * v + 2], 1.0)).xyz; }
vec3 normal(uint v) { return uNormalMatrix * vec3(vertices[6 * v + 3], vertices[6 * v + 4], vertices[6 * v + 5]); }

void main() {
    uint triangle = gl_GlobalInvocationID.x;
    if (triangle >= uTriangleCount) return;
    uint i0 = indices[3 * triangle], i1 = indices[3 * triangle + 1], i2 = indices[3 * triangle + 2];
    vec3 p0 = position(i0), u = position(i1) - p0, v = position(i2) - p0;
    vec3 n0 = normal(i0), n1 = normal(i1), n2 = normal(i2);
    vec3 middle = p0 + (u + v) / 3.0;
    float scale = uSamplesPerUnit / max(dot(middle - uEyePosition, uViewAxis), uNearPlane);
    vec3 plane = cross(u, v);
    float doubleArea = length(plane);
    if (!(doubleArea > 0.0)) return;
    plane /= doubleArea;
    vec3 e1 = uViewRight - plane * dot(uViewRight, plane);
    e1 = dot(e1, e1) > 1e-8 ? normalize(e1) : normalize(u);  // seen edge-on: any in-plane axis
    vec3 e2 = cross(plane, e1);
    // The triangle in lattice units (one unit = one sample at depth d), origin at the world origin.
    vec2 q0 = scale * vec2(dot(p0, e1), dot(p0, e2));
    vec2 qu = scale * vec2(dot(u, e1), dot(u, e2)), qv = scale * vec2(dot(v, e1), dot(v, e2));
    float det = qu.x * qv.y - qu.y * qv.x;
    float spacing = 1.0;
    float area = 0.5 * abs(det);
    bool bounded = area > uMaxTriangleSamples;
    if (bounded) spacing = sqrt(area / uMaxTriangleSamples);
    // The lattice is walked over the triangle's bounding box in row-major order, POINT_CHUNK
    // points per invocation along y (llvmpipe stops a loop after 65535 iterations); a sliver's box
    // past the chunks dispatched gets a coarser lattice too.
    vec2 lo = min(q0, min(q0 + qu, q0 + qv)), hi = max(q0, max(q0 + qu, q0 + qv));
    uint budget = uChunks * POINT_CHUNK;
    float columns = floor(hi.x / spacing) - floor(lo.x / spacing) + 2.0;
    float rows = floor(hi.y / spacing) - floor(lo.y / spacing) + 2.0;
    if (columns * rows > float(budget)) {
        spacing *= sqrt(columns * rows / float(budget)) * 1.01;
        columns = floor(hi.x / spacing) - floor(lo.x / spacing) + 2.0;
        rows = floor(hi.y / spacing) - floor(lo.y / spacing) + 2.0;
        bounded = true;
    }
    if (bounded && gl_GlobalInvocationID.y == 0u) atomicCounterIncrement(uTrianglesBounded);
    uint cols = uint(columns), total = cols * uint(rows);
    uint first = gl_GlobalInvocationID.y * POINT_CHUNK;
    if (first >= total) return;
    uint key = hashUint(hashUint(uSeed) ^ uObjectId);
    vec2 phase = vec2(hashUnit(key), hashUnit(hashUint(key ^ 0x9e3779b9u)));
    ivec2 origin = ivec2(floor(lo / spacing - phase)) ;
    uint last = min(first + POINT_CHUNK, total);
    // Texture coordinates at the corners and their change per lattice step (a = 1 along qu, b
    // along qv), through the transform: the gradients textureGrad filters over.
    vec2 t0 = vec2(0.0), tu = vec2(0.0), tv = vec2(0.0), gradX = vec2(0.0), gradY = vec2(0.0);
    if (uTextured) {
        t0 = transformTexCoord(uBaseColorTransform, texCoordOf(i0));
        tu = transformTexCoord(uBaseColorTransform, texCoordOf(i1)) - t0;
        tv = transformTexCoord(uBaseColorTransform, texCoordOf(i2)) - t0;
        gradX = spacing * (tu * qv.y - tv * qu.y) / det;
        gradY = spacing * (tv * qu.x - tu * qv.x) / det;
    }
    bool colored = uColorOffset >= 0;
    vec4 c0 = vec4(1.0), c1 = vec4(1.0), c2 = vec4(1.0);
    if (colored) {
        c0 = colorOf(i0);
        c1 = colorOf(i1);
        c2 = colorOf(i2);
    }
    for (uint q = first; q < last; ++q) {
        ivec2 cell = origin + ivec2(int(q % cols), int(q / cols));
        vec2 d = (vec2(cell) + phase) * spacing - q0;
        // Barycentric coordinates of the lattice point: d = a qu + b qv.
        float a = (d.x * qv.y - d.y * qv.x) / det;
        float b = (qu.x * d.y - qu.y * d.x) / det;
        if (a < 0.0 || b < 0.0 || a + b > 1.0) continue;
        uint sampleKey = hashUint(key ^ hashUint(uint(cell.x) * 0x85ebca6bu ^ uint(cell.y)));
        vec4 detail = vec4(1.0);  // texel x COLOR_0
        if (uTextured) detail = textureGrad(uBaseColorTexture, t0 + a * tu + b * tv, gradX, gradY);
        if (colored) detail *= (1.0 - a - b) * c0 + a * c1 + b * c2;
        float keep = uAlphaCutoff > 0.0 ? (uFactorAlpha * detail.a >= uAlphaCutoff ? uAlpha : 0.0) : uAlpha * detail.a;
        if (!(hashUnit(sampleKey) < keep)) continue;
        uint slot = atomicCounterIncrement(uPointsWanted);
        if (slot >= uCapacity) continue;
        vec3 p = p0 + a * u + b * v;
        vec3 n = normalize((1.0 - a - b) * n0 + a * n1 + b * n2);
        points[slot] = ScreenDoorPoint(p.x, p.y, p.z, packSnorm4x8(vec4(n, 0.0)), uObjectId,
                                       packHalf2x16(detail.rg), packHalf2x16(vec2(detail.b, 0.0)));
    }
}
