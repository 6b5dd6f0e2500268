// Bucket of a fragment: the pixel's depth range split into uBuckets uniform intervals of eye
// distance (window depth is 1/z-like, so uniform window-depth buckets would crowd the far end).
// Distance from reversed-Z window depth: d = B / (z + A) with A = P[2][2], B = P[3][2].
#include "bindings.h"
#include "peel_bindings.h"

layout(binding = BIND_PEEL_PREVIOUS) uniform sampler2D uRange;
layout(binding = BIND_OPAQUE_DEPTH) uniform sampler2D uOpaqueDepth;
uniform int uBuckets;
uniform float uDepthA;
uniform float uDepthB;

float eyeDistance(float z) { return uDepthB / (z + uDepthA); }

int bucketOf(ivec2 pixel, float z) {
    vec2 range = texelFetch(uRange, pixel, 0).rg;
    // Nothing nearer than the near plane; nothing behind the opaque surface is drawn.
    float nearZ = clamp(range.r, 0.0, 1.0);
    float farZ = max(clamp(-range.g, 0.0, 1.0), texelFetch(uOpaqueDepth, pixel, 0).r);
    float dn = eyeDistance(nearZ);
    float df = eyeDistance(farZ);
    if (!(df > dn)) return 0;
    float t = (eyeDistance(z) - dn) / (df - dn);
    return clamp(int(floor(t * float(uBuckets))), 0, uBuckets - 1);
}
