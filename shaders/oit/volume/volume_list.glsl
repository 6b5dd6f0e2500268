// The volumetric resolve of ll-volume and abuffer-volume: a pixel's linked list walked front to
// back in the exact order of ordered_composite.glsl, through the media of the volumes the ray
// is in (render/volume_composite.hpp is the same model on the CPU, and says why it keeps a set
// of volumes rather than the paper's running sums). Thin surfaces composite with their alpha in
// the same walk. Shared by the fragment and compute resolves (abuffer_resolve.*, VOLUME
// defined); the colour and transmittance of compositeFragment's signature are unused, the walk
// keeps a transmittance per channel. With STRATA_RGB_TRANSMITTANCE (a scene with coloured
// filters) a glass surface filters that transmittance per channel (oit/packed_color.glsl).
#include "oit/abuffer_storage.glsl"
#include "oit/node_fetch.glsl"
#include "oit/packed_color.glsl"
#include "oit/volume/volume_bindings.h"

layout(binding = BIND_VOLUME_MEDIA) uniform samplerBuffer uVolumeMedia;
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

float fragmentDepth(uint i) { return nodeDepth(i); }
uint fragmentObject(uint i) { return nodeObject(i); }
uint fragmentPrimitive(uint i) { return nodePrimitive(i) & VOLUME_PRIMITIVE_MASK; }
void compositeFragment(uint i, inout vec3 color, inout Transmittance transmittance);  // the walk's step, below

// Links hold index + 1 with 0 ending the list, so "link - 1" ends at 0xFFFFFFFF.
#define FOR_EACH_FRAGMENT(i) for (uint i = gFirstNode; i != 0xFFFFFFFFu; i = nodeNext(i) - 1u)
#include "oit/ordered_composite.glsl"

// The walk: the volumes the ray is in, as VOLUME_MAX_NESTED = 8 slots held in vectors (object
// ids, entries minus exits, and each slot's medium per channel; a count of 0 is a free slot), so
// that finding a volume's slot is a few vector compares with no loop and no array in memory.
// Then the medium of the slots with a positive count, the radiance gathered and the
// transmittance so far, and the farthest window depth reached (reversed-Z: smaller is farther;
// the walk starts at the eye).
//
// The medium is not kept by adding on entry and subtracting on exit (a large tau leaving would
// leave round-off behind in the others): after every crossing it is the sum of the members'
// media, selected from the slots, so it is exactly zero when no volume is left. Selecting from
// registers costs the same whatever the nesting: re-reading the table only where one of several
// overlapping volumes is left made a branch llvmpipe runs for every lane whether or not any
// takes it, 50 of the 130 ms of ll-volume's resolve on builtin:slabs:16, where none overlap.
uvec4 gSlotObjectLo, gSlotObjectHi;
ivec4 gSlotCountLo, gSlotCountHi;
vec4 gSlotTauLo[3], gSlotTauHi[3];          // per channel r, g, b
vec4 gSlotScatterLo[3], gSlotScatterHi[3];
int gMembers;   // slots with a positive count
uint gIgnored;  // volume fragments with no slot left, reported after the walk
vec3 gTau;
vec3 gScatter;
vec3 gRadiance;
vec3 gTransmittance;
bool gAtEye;
float gReachedDepth;
float gRayScale;    // distance along the ray per unit of eye depth
float gInscattered; // L^s for this pixel's ray

// (1 - e^{-tau d}) / tau per channel without cancellation, given T = e^{-tau d}: a series for
// tau d < 0.03 (truncation below 1e-8 relative), d itself at tau = 0; (1 - T) / tau above.
vec3 segmentIntegral(vec3 tau, float len, vec3 transmittance) {
    vec3 x = tau * len;
    vec3 series = len * (1.0 - x * (0.5 - x * (1.0 / 6.0 - x * (1.0 / 24.0))));
    vec3 direct = (1.0 - transmittance) / max(tau, vec3(1e-30));
    return mix(direct, series, lessThan(x, vec3(0.03)));
}

// Moves the walk to window depth d through the current medium. Lengths come from the
// difference of window depths, K (d_a - d_b) / (w_a w_b) with w = d + n / (f - n): no
// cancellation of two large eye depths, so thin segments stay exact at any near/far ratio.
void advanceTo(float d) {
    // Free space (no volume around the ray, so tau and scatter are zero): only the position moves,
    // which is the whole cost of the walk on a scene without volumes.
    if (gMembers <= 0) {
        gReachedDepth = gAtEye ? d : min(gReachedDepth, d);
        gAtEye = false;
        return;
    }
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
    vec3 transmittance = exp(-gTau * len);
    gRadiance += gTransmittance * gInscattered * gScatter * segmentIntegral(gTau, len, transmittance);
    gTransmittance *= transmittance;
}

vec3 mediumTau(uint object) { return texelFetch(uVolumeMedia, int(2u * object)).rgb; }
vec3 mediumScatter(uint object) { return texelFetch(uVolumeMedia, int(2u * object + 1u)).rgb; }

// The members (slots with a positive count), and their media summed: selected, not
// multiplied, so an infinite tau in a free slot leaves no NaN behind.
void sumMembers() {
    bvec4 lo = greaterThan(gSlotCountLo, ivec4(0)), hi = greaterThan(gSlotCountHi, ivec4(0));
    ivec4 members = ivec4(lo) + ivec4(hi);
    gMembers = members.x + members.y + members.z + members.w;
    const vec4 ones = vec4(1.0), none = vec4(0.0);
    for (int c = 0; c < 3; ++c) {
        gTau[c] = dot(mix(none, gSlotTauLo[c], lo), ones) + dot(mix(none, gSlotTauHi[c], hi), ones);
        gScatter[c] = dot(mix(none, gSlotScatterLo[c], lo), ones) + dot(mix(none, gSlotScatterHi[c], hi), ones);
    }
}

// Slots 0-3 in `lo` and 4-7 in `hi` as the bits 0-7 of one mask.
uint slotBits(bvec4 lo, bvec4 hi) {
    uvec4 l = uvec4(lo) * uvec4(1u, 2u, 4u, 8u), h = uvec4(hi) * uvec4(16u, 32u, 64u, 128u);
    return l.x | l.y | l.z | l.w | h.x | h.y | h.z | h.w;
}

// Entering (+1) or leaving (-1) a volume: its slot's count changes (0 frees the slot), or it
// takes the first free slot. Written without branches on the common path (vector selects): in
// a SIMD resolve every branch that lanes take differently costs both sides.
void crossVolume(uint object, int step) {
    ivec4 lo = ivec4(equal(gSlotObjectLo, uvec4(object))) * ivec4(notEqual(gSlotCountLo, ivec4(0)));
    ivec4 hi = ivec4(equal(gSlotObjectHi, uvec4(object))) * ivec4(notEqual(gSlotCountHi, ivec4(0)));
    uint mine = slotBits(bvec4(lo), bvec4(hi));
    uint free = slotBits(equal(gSlotCountLo, ivec4(0)), equal(gSlotCountHi, ivec4(0)));
    // Its own slot, else the lowest free one (the lowest set bit of `free`).
    uint target = mine != 0u ? mine : free & (~free + 1u);
    gIgnored += target == 0u ? 1u : 0u;  // no slot: ignored (and reported once per pixel)
    bvec4 tLo = notEqual(uvec4(target) & uvec4(1u, 2u, 4u, 8u), uvec4(0u));
    bvec4 tHi = notEqual(uvec4(target) & uvec4(16u, 32u, 64u, 128u), uvec4(0u));
    gSlotObjectLo = mix(gSlotObjectLo, uvec4(object), tLo);
    gSlotObjectHi = mix(gSlotObjectHi, uvec4(object), tHi);
    gSlotCountLo += ivec4(tLo) * step;
    gSlotCountHi += ivec4(tHi) * step;
    // The slot holds this volume's medium (leaving, it is its own slot and medium already).
    vec3 tau = mediumTau(object), scatter = mediumScatter(object);
    for (int c = 0; c < 3; ++c) {
        gSlotTauLo[c] = mix(gSlotTauLo[c], vec4(tau[c]), tLo);
        gSlotTauHi[c] = mix(gSlotTauHi[c], vec4(tau[c]), tHi);
        gSlotScatterLo[c] = mix(gSlotScatterLo[c], vec4(scatter[c]), tLo);
        gSlotScatterHi[c] = mix(gSlotScatterHi[c], vec4(scatter[c]), tHi);
    }
    sumMembers();
}

void compositeFragment(uint i, inout vec3 color, inout Transmittance transmittance) {
    advanceTo(nodeDepth(i));
    uint p = nodePrimitive(i);
    if ((p & VOLUME_FLAG_MEDIUM) != 0u) {
        crossVolume(nodeObject(i), (p & VOLUME_FLAG_ENTRY) != 0u ? 1 : -1);
        return;
    }
    const uvec2 packedColor = nodeColor(i);
#ifdef STRATA_RGB_TRANSMITTANCE
    compositePacked(packedColor.x, packedColor.y, gRadiance, gTransmittance);
#else
    vec2 rg = unpackHalf2x16(packedColor.x);
    vec2 ba = unpackHalf2x16(packedColor.y);
    gRadiance += gTransmittance * ba.y * vec3(rg, ba.x);
    gTransmittance *= 1.0 - ba.y;
#endif
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
    gTau = vec3(0.0);
    gScatter = vec3(0.0);
    gMembers = 0;
    gIgnored = 0u;
    gSlotObjectLo = gSlotObjectHi = uvec4(0u);
    gSlotCountLo = gSlotCountHi = ivec4(0);
    for (int c = 0; c < 3; ++c) gSlotTauLo[c] = gSlotTauHi[c] = gSlotScatterLo[c] = gSlotScatterHi[c] = vec4(0.0);
    for (int k = 0; k < uEyeInsideCount && k < int(VOLUME_MAX_NESTED); ++k) crossVolume(uEyeInsideObject[k], 1);
}

// The pixel's surfaces and volumes in depth order over `opaque`.
vec3 resolvePixel(ivec2 pixel, vec3 opaque) {
    gFirstNode = imageLoad(uHeads, pixel).r - 1u;
    beginWalk(pixel);
    vec3 unusedColor = vec3(0.0);
    Transmittance unusedTransmittance = Transmittance(1.0);
    compositeInDepthOrder(unusedColor, unusedTransmittance);
#ifdef LIST_TAIL
    // Overflowed thin surfaces, one approximate layer behind the stored fragments.
    vec3 tailColor = vec3(0.0);
    Transmittance tailTransmittance = Transmittance(1.0);
    compositeTail(pixel, tailColor, tailTransmittance);
    gRadiance += gTransmittance * tailColor;
    gTransmittance *= tailTransmittance;
#endif
    advanceTo(texelFetch(uOpaqueDepth, pixel, 0).r);
    if (gIgnored > 0u) atomicAdd(volumeStats[VOLUME_STAT_NESTING_OVERFLOW], gIgnored);
    return gRadiance + gTransmittance * opaque;
}
