// The volumetric resolve of ll-volume and abuffer-volume: a pixel's linked list walked front to
// back in the exact order of ordered_composite.glsl, through the media of the volumes the ray
// is in (render/volume_composite.hpp is the same model on the CPU, and says why it keeps a set
// of volumes rather than the paper's running sums). Thin surfaces composite with their alpha in
// the same walk. Shared by the fragment and compute resolves (abuffer_resolve.*, VOLUME
// defined); the colour and transmittance of compositeFragment's signature are unused, the walk
// keeps a transmittance per channel.
#include "oit/abuffer_storage.glsl"
#include "oit/volume/volume_bindings.h"

layout(std430, binding = BIND_VOLUME_OBJECTS) readonly buffer VolumeObjects {
    VolumeObject volumeObjects[];
};
layout(std430, binding = BIND_VOLUME_STATS) buffer VolumeStats {
    uint volumeStats[];
};
layout(binding = BIND_OPAQUE_DEPTH) uniform sampler2D uOpaqueDepth;

uniform float uDepthScale;   // n f / (f - n): eye depth = uDepthScale / (d + uDepthOffset)
uniform vec2 uInvFocal;      // 1 / projection[0][0], 1 / projection[1][1]
uniform vec2 uFrameSize;     // pixels
uniform mat3 uEyeToWorld;    // the camera's rotation
uniform vec3 uLightDirection;
uniform float uAmbientRadiance;   // L^a
uniform float uLightIrradiance;   // L^r
uniform int uEyeInsideCount;      // the volumes around the eye, tested on the CPU per frame
uniform uint uEyeInsideObject[VOLUME_MAX_NESTED];

uint gFirstNode;  // the pixel's list head as a node index, 0xFFFFFFFF for an empty list

float fragmentDepth(uint i) { return nodes[i].depth; }
uint fragmentObject(uint i) { return nodes[i].objectId; }
uint fragmentPrimitive(uint i) { return nodes[i].primitiveId & VOLUME_PRIMITIVE_MASK; }
void compositeFragment(uint i, inout vec3 color, inout float transmittance);  // the walk's step, below

// Links hold index + 1 with 0 ending the list, so "link - 1" ends at 0xFFFFFFFF.
#define FOR_EACH_FRAGMENT(i) for (uint i = gFirstNode; i != 0xFFFFFFFFu; i = nodes[i].next - 1u)
#include "oit/ordered_composite.glsl"

// The walk: the volumes the ray is in (object, entries minus exits), the radiance gathered and
// the transmittance so far, and the farthest window depth reached (reversed-Z: smaller is
// farther; the walk starts at the eye).
uint gInsideObject[VOLUME_MAX_NESTED];
int gInsideCount[VOLUME_MAX_NESTED];
int gInsideSize;
vec3 gRadiance;
vec3 gTransmittance;
bool gAtEye;
float gReachedDepth;
float gRayScale;    // distance along the ray per unit of eye depth
float gInscattered; // L^s for this pixel's ray

// (1 - e^{-tau d}) / tau without cancellation: a series for small tau d, d itself at tau = 0.
float segmentIntegral(float tau, float len) {
    float x = tau * len;
    if (x < 0.03) return len * (1.0 - x * (0.5 - x * (1.0 / 6.0 - x * (1.0 / 24.0))));
    return (1.0 - exp(-x)) / tau;
}

// Moves the walk to window depth d through the current medium. Lengths come from the
// difference of window depths, K (d_a - d_b) / (w_a w_b) with w = d + n / (f - n): no
// cancellation of two large eye depths, so thin segments stay exact at any near/far ratio.
void advanceTo(float d) {
    float w = d + uDepthOffset;
    float len;
    if (gAtEye) {
        len = uDepthScale / w;
    } else {
        if (d >= gReachedDepth) return;
        len = uDepthScale * (gReachedDepth - d) / ((gReachedDepth + uDepthOffset) * w);
    }
    gAtEye = false;
    gReachedDepth = d;
    len *= gRayScale;
    vec3 tau = vec3(0.0), scatter = vec3(0.0);
    bool any = false;
    for (int k = 0; k < gInsideSize; ++k) {
        if (gInsideCount[k] <= 0) continue;
        VolumeObject v = volumeObjects[gInsideObject[k]];
        tau += vec3(v.tauR, v.tauG, v.tauB);
        scatter += vec3(v.scatterR, v.scatterG, v.scatterB);
        any = true;
    }
    if (!any) return;
    vec3 integral = vec3(segmentIntegral(tau.r, len), segmentIntegral(tau.g, len), segmentIntegral(tau.b, len));
    gRadiance += gTransmittance * gInscattered * scatter * integral;
    gTransmittance *= exp(-tau * len);
}

// Entering (+1) or leaving (-1) a volume.
void crossVolume(uint object, int step) {
    for (int k = 0; k < gInsideSize; ++k) {
        if (gInsideObject[k] != object) continue;
        gInsideCount[k] += step;
        if (gInsideCount[k] == 0) {
            gInsideSize--;
            gInsideObject[k] = gInsideObject[gInsideSize];
            gInsideCount[k] = gInsideCount[gInsideSize];
        }
        return;
    }
    if (gInsideSize == int(VOLUME_MAX_NESTED)) {
        atomicAdd(volumeStats[VOLUME_STAT_NESTING_OVERFLOW], 1u);
        return;
    }
    gInsideObject[gInsideSize] = object;
    gInsideCount[gInsideSize] = step;
    gInsideSize++;
}

void compositeFragment(uint i, inout vec3 color, inout float transmittance) {
    advanceTo(nodes[i].depth);
    uint p = nodes[i].primitiveId;
    if ((p & VOLUME_FLAG_MEDIUM) != 0u) {
        crossVolume(nodes[i].objectId, (p & VOLUME_FLAG_ENTRY) != 0u ? 1 : -1);
        return;
    }
    vec2 rg = unpackHalf2x16(nodes[i].colorRG);
    vec2 ba = unpackHalf2x16(nodes[i].colorBA);
    gRadiance += gTransmittance * ba.y * vec3(rg, ba.x);
    gTransmittance *= 1.0 - ba.y;
}

void beginWalk(ivec2 pixel) {
    vec2 ndc = (vec2(pixel) + 0.5) / uFrameSize * 2.0 - 1.0;
    vec3 eyeDirection = vec3(ndc * uInvFocal, -1.0);  // unit eye depth, as the CPU's pixelRay
    gRayScale = length(eyeDirection);
    float cosTheta = dot(normalize(uEyeToWorld * eyeDirection), uLightDirection);
    // L^s = L^a + L^r 3 / (16 pi) (1 + cos^2 theta): the Rayleigh phase function (section 2.1).
    gInscattered = uAmbientRadiance + uLightIrradiance * (3.0 / (16.0 * 3.14159265358979)) * (1.0 + cosTheta * cosTheta);
    gRadiance = vec3(0.0);
    gTransmittance = vec3(1.0);
    gAtEye = true;
    gReachedDepth = 1.0;
    gInsideSize = 0;
    for (int k = 0; k < uEyeInsideCount && k < int(VOLUME_MAX_NESTED); ++k) {
        gInsideObject[k] = uEyeInsideObject[k];
        gInsideCount[k] = 1;
        gInsideSize++;
    }
}

// The pixel's surfaces and volumes in depth order over `opaque`.
vec3 resolvePixel(ivec2 pixel, vec3 opaque) {
    gFirstNode = imageLoad(uHeads, pixel).r - 1u;
    beginWalk(pixel);
    vec3 unusedColor = vec3(0.0);
    float unusedTransmittance = 1.0;
    compositeInDepthOrder(unusedColor, unusedTransmittance);
#ifdef LIST_TAIL
    // Overflowed thin surfaces, one approximate layer behind the stored fragments.
    vec3 tailColor = vec3(0.0);
    float tailTransmittance = 1.0;
    compositeTail(pixel, tailColor, tailTransmittance);
    gRadiance += gTransmittance * tailColor;
    gTransmittance *= tailTransmittance;
#endif
    advanceTo(texelFetch(uOpaqueDepth, pixel, 0).r);
    return gRadiance + gTransmittance * opaque;
}
