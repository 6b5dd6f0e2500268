#version 450 core
// Object-space point sampling (Sen et al. 4.1): one invocation per triangle lays a lattice of
// about one point per supersampled pixel on the triangle turned parallel to the image plane at
// its centroid's view depth d, n = (N h_im / (d h))^2 A points (4.1.1), uniform in the triangle's
// (u, v) parameterization with a random phase per triangle, and keeps each with probability
// alpha from its own random number (4.1.2). Kept points are appended for the point pass. The
// lattice is fixed on the surface (object space), so where the surface turns away from the eye
// more points fall in each pixel and the silhouette grows opaque.
//
// Bounds: d is at least the near plane; a triangle wanting more than uMaxTriangleSamples points
// gets a coarser lattice of that many and is counted; points past uCapacity are counted, not
// written (the host grows the buffer and samples again).
#include "bindings.h"
#include "screendoor_bindings.h"
#include "random_hash.glsl"

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
uniform float uSamplesPerUnit;  // supersampled pixels per scene unit at depth 1
uniform float uNearPlane;
uniform float uMaxTriangleSamples;
uniform uint uCapacity;

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
    // The triangle unfolded in sample units: (0, 0), (lu, 0), (k, h).
    float lu = length(u) * scale;
    if (!(lu > 0.0)) return;
    float k = dot(u, v) * scale * scale / lu;
    float h = sqrt(max(dot(v, v) * scale * scale - k * k, 0.0));
    if (!(h > 0.0)) return;
    float spacing = 1.0;
    float area = 0.5 * lu * h;
    if (area > uMaxTriangleSamples) {
        spacing = sqrt(area / uMaxTriangleSamples);
        atomicCounterIncrement(uTrianglesBounded);
    }
    uint key = hashUint(hashUint(hashUint(uSeed) ^ uObjectId) ^ triangle);
    vec2 phase = vec2(hashUnit(key), hashUnit(hashUint(key ^ 0x9e3779b9u)));
    int rows = int(ceil(h / spacing));
    for (int j = 0; j < rows; ++j) {
        float y = (float(j) + phase.y) * spacing;
        if (y >= h) break;
        float b = y / h;
        float left = k * b, right = lu + (k - lu) * b;  // the row's extent between the edges
        int first = int(ceil(left / spacing - phase.x)), last = int(ceil(right / spacing - phase.x));
        for (int i = first; i < last; ++i) {
            float x = (float(i) + phase.x) * spacing;
            uint sampleKey = hashUint(key ^ hashUint(uint(i) * 0x85ebca6bu ^ uint(j)));
            if (!(hashUnit(sampleKey) < uAlpha)) continue;
            float a = (x - b * k) / lu;
            uint slot = atomicCounterIncrement(uPointsWanted);
            if (slot >= uCapacity) continue;
            vec3 p = p0 + a * u + b * v;
            vec3 n = normalize((1.0 - a - b) * n0 + a * n1 + b * n2);
            points[slot] = ScreenDoorPoint(p.x, p.y, p.z, packSnorm4x8(vec4(n, 0.0)), uObjectId);
        }
    }
}
