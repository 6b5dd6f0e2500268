#version 450 core
// Resolve of one peeled layer (f2b-ll, f2b-fab, f2b-kb, with ANCHOR; with DUAL the front and
// back layers of dual-ll, dual-fab): the pixel's stored fragments (and with ANCHOR the layer's
// anchor, kept apart by the peel pass with its colour and ids) are one layer, so they composite in scene
// order (core/render/depth_order.hpp, step 3: object, then primitive), found by repeated
// selection: no sort arrays (a layer is one fragment but where surfaces coincide), O(n^2) in
// the coincident count, exact for any. The result goes out as (premultiplied colour,
// 1 - transmittance). The host blends output 0 under the front
// accumulation and, with DUAL, output 1 over the back accumulation. An empty side writes 0,
// neutral under both blends; without DUAL a pixel with nothing is discarded, so with ANCHOR the
// samples-passed count of the pass is the number of anchors.
// STRATA_RGB_TRANSMITTANCE (a scene with coloured filters): the transmittance is per channel, and
// no blend factor can scale one target by what another holds, so the pass reads the texel it
// writes of each accumulation and its "passes" target (after glTextureBarrier; outputs 0, 1 the
// front, 2, 3 the back) and writes them composited, without blending.
// ANCHORS_ONLY (with ANCHOR): the build the host draws when the capture stored nothing anywhere,
// f2b's blend of the anchors, without the storage. It is a build of its own, not a uniform's
// branch: llvmpipe runs every branch of a shader for every lane, masked, so the storage reads
// behind a uniform that skipped them still cost their time (f2b-ll's resolve on
// builtin:layers:16 at 256x256: 12.7 ms with the branch, 5.8 as a build of its own, f2b's
// blend 5.4).
#include "bindings.h"
#include "peel_bindings.h"
#include "oit/packed_color.glsl"

#ifdef ANCHOR
#include "layer_bindings.h"
layout(binding = BIND_ANCHOR) uniform usampler2D uAnchor;
uvec4 gAnchor;  // packed colour, object id + 1, primitive id
#endif

#ifndef ANCHORS_ONLY  // the storage, and a layer's order within it
#include "layer_storage.glsl"

#if defined(LAYER_LIST)
uint gFirst;  // the side's list head as a node index, 0xFFFFFFFF for an empty list
float fragmentDepth(uint i) { return nodes[i].depth; }
uint fragmentObject(uint i) { return nodes[i].objectId; }
uint fragmentPrimitive(uint i) { return nodes[i].primitiveId; }
void compositeFragment(uint i, inout vec3 color, inout Transmittance transmittance) {
    compositePacked(nodes[i].colorRG, nodes[i].colorBA, color, transmittance);
}
#define FOR_EACH_FRAGMENT(i) for (uint i = gFirst; i != 0xFFFFFFFFu; i = nodes[i].next - 1u)
bool singleFragment() { return nodes[gFirst].next == 0u; }
bool selectSide(ivec2 pixel, int side) {
    gFirst = imageLoad(uHeads, sidePixel(pixel, side)).r - 1u;
    return gFirst != 0xFFFFFFFFu;
}
#else
uint gFirst, gEnd;  // the side's entries [gFirst, gEnd)
float fragmentDepth(uint i) { return entries[i].depth; }
uint fragmentObject(uint i) { return entries[i].objectId; }
uint fragmentPrimitive(uint i) { return entries[i].primitiveId; }
void compositeFragment(uint i, inout vec3 color, inout Transmittance transmittance) {
    compositePacked(entries[i].colorRG, entries[i].colorBA, color, transmittance);
}
#define FOR_EACH_FRAGMENT(i) for (uint i = gFirst; i < gEnd; ++i)
bool singleFragment() { return gEnd == gFirst + 1u; }
bool selectSide(ivec2 pixel, int side) {
    gFirst = firstEntry(pixel, side);
#if defined(LAYER_FAB)
    uint count = min(imageLoad(uCounts, sidePixel(pixel, side)).r, uCapacity);
#else
    uint count = 0u;
    while (count < uCapacity && entries[gFirst + count].objectId != kUnclaimed) count++;
#endif
    gEnd = gFirst + count;
    return count > 0u;
}
#endif

#define NO_FRAGMENT 0xFFFFFFFFu

#ifdef ANCHOR
// The anchor as fragment index kAnchor: its own accessors, the storage's for every other index.
const uint kAnchor = 0xFFFFFFFEu;
#define ANCHOR_OR(i, anchorValue, storedValue) ((i) == kAnchor ? (anchorValue) : (storedValue))
uint objectOf(uint i) { return ANCHOR_OR(i, gAnchor.z - 1u, fragmentObject(i)); }
uint primitiveOf(uint i) { return ANCHOR_OR(i, gAnchor.w, fragmentPrimitive(i)); }
float depthOf(uint i) { return ANCHOR_OR(i, 1.0, fragmentDepth(i)); }  // one per (object, primitive): never compared
void compositeAny(uint i, inout vec3 color, inout Transmittance transmittance) {
    if (i == kAnchor) {
        compositePacked(gAnchor.x, gAnchor.y, color, transmittance);
    } else {
        compositeFragment(i, color, transmittance);
    }
}
#else
uint objectOf(uint i) { return fragmentObject(i); }
uint primitiveOf(uint i) { return fragmentPrimitive(i); }
float depthOf(uint i) { return fragmentDepth(i); }
void compositeAny(uint i, inout vec3 color, inout Transmittance transmittance) {
    compositeFragment(i, color, transmittance);
}
#endif

// Scene order; equal keys (one primitive cannot cover a pixel twice) fall back to the index so
// the order stays total.
bool sceneBefore(uint a, uint b) {
    uint oa = objectOf(a), ob = objectOf(b);
    if (oa != ob) return oa < ob;
    uint pa = primitiveOf(a), pb = primitiveOf(b);
    if (pa != pb) return pa < pb;
    float da = depthOf(a), db = depthOf(b);
    if (da != db) return da > db;
    return a < b;
}

// `stored`: whether the storage holds any of the layer's fragments.
void compositeLayer(bool stored, inout vec3 color, inout Transmittance transmittance) {
#ifdef ANCHOR
    // Where nothing coincides (most pixels) the layer is its anchor: no storage, no selection.
    if (!stored) {
        compositeAny(kAnchor, color, transmittance);
        return;
    }
#else
    // Where nothing coincides (most pixels) the layer is one fragment: no selection.
    if (singleFragment()) {
        compositeFragment(gFirst, color, transmittance);
        return;
    }
#endif
    uint done = NO_FRAGMENT;
    while (true) {
        uint best = NO_FRAGMENT;
#ifdef ANCHOR
        if (done == NO_FRAGMENT || sceneBefore(done, kAnchor)) best = kAnchor;
#endif
        FOR_EACH_FRAGMENT(i) {
            if (done != NO_FRAGMENT && !sceneBefore(done, i)) continue;
            if (best == NO_FRAGMENT || sceneBefore(i, best)) best = i;
        }
        if (best == NO_FRAGMENT) break;
        compositeAny(best, color, transmittance);
        done = best;
    }
}

#endif  // !ANCHORS_ONLY

// A layer composited: its premultiplied colour and what it lets through.
struct Layer {
    vec3 color;
    Transmittance transmittance;
};
const Layer kNothing = Layer(vec3(0.0), Transmittance(1.0));

#ifndef ANCHORS_ONLY
Layer compositeSide(ivec2 pixel, int side) {
    bool stored = selectSide(pixel, side);
#ifndef ANCHOR
    if (!stored) return kNothing;
#endif
    Layer layer = kNothing;
    compositeLayer(stored, layer.color, layer.transmittance);
    return layer;
}
#endif

#ifdef STRATA_RGB_TRANSMITTANCE
layout(binding = BIND_PEEL_ACCUM) uniform sampler2D uAccum;
layout(binding = BIND_PEEL_ACCUM_FILTER) uniform sampler2D uAccumPasses;
layout(location = 0) out vec4 outFront;
layout(location = 1) out vec4 outFrontPasses;
// Under the front accumulation.
void writeFront(ivec2 pixel, Layer layer) {
    vec3 t = texelFetch(uAccumPasses, pixel, 0).rgb;
    outFront = vec4(texelFetch(uAccum, pixel, 0).rgb + t * layer.color, 1.0);
    outFrontPasses = vec4(t * layer.transmittance, 1.0);
}
#ifdef DUAL
layout(binding = BIND_PEEL_BACK_ACCUM) uniform sampler2D uBackAccum;
layout(binding = BIND_PEEL_BACK_ACCUM_FILTER) uniform sampler2D uBackAccumPasses;
layout(location = 2) out vec4 outBack;
layout(location = 3) out vec4 outBackPasses;
// Over the back accumulation.
void writeBack(ivec2 pixel, Layer layer) {
    outBack = vec4(layer.color + layer.transmittance * texelFetch(uBackAccum, pixel, 0).rgb, 1.0);
    outBackPasses = vec4(layer.transmittance * texelFetch(uBackAccumPasses, pixel, 0).rgb, 1.0);
}
#endif
#else
layout(location = 0) out vec4 outFront;
void writeFront(ivec2 pixel, Layer layer) { outFront = vec4(layer.color, 1.0 - layer.transmittance); }
#ifdef DUAL
layout(location = 1) out vec4 outBack;
void writeBack(ivec2 pixel, Layer layer) { outBack = vec4(layer.color, 1.0 - layer.transmittance); }
#endif
#endif

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
#ifdef DUAL
    writeFront(pixel, compositeSide(pixel, 0));
    writeBack(pixel, compositeSide(pixel, 1));
#elif defined(ANCHOR)
    gAnchor = texelFetch(uAnchor, pixel, 0);
    if (gAnchor.z == 0u) discard;  // no layer here (coincident fragments come with an anchor)
#ifdef ANCHORS_ONLY
    Layer anchor = kNothing;
    compositePacked(gAnchor.x, gAnchor.y, anchor.color, anchor.transmittance);
    writeFront(pixel, anchor);
#else
    writeFront(pixel, compositeSide(pixel, 0));
#endif
#else
    if (!selectSide(pixel, 0)) discard;
    writeFront(pixel, compositeSide(pixel, 0));
#endif
}
