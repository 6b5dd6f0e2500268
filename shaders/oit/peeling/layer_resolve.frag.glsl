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
#include "bindings.h"
#include "layer_storage.glsl"
#include "oit/packed_color.glsl"

#if defined(LAYER_LIST)
uint gFirst;  // the side's list head as a node index, 0xFFFFFFFF for an empty list
float fragmentDepth(uint i) { return nodes[i].depth; }
uint fragmentObject(uint i) { return nodes[i].objectId; }
uint fragmentPrimitive(uint i) { return nodes[i].primitiveId; }
void compositeFragment(uint i, inout vec3 color, inout float transmittance) {
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
void compositeFragment(uint i, inout vec3 color, inout float transmittance) {
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
#include "layer_bindings.h"
layout(binding = BIND_ANCHOR) uniform usampler2D uAnchor;
// The anchor as fragment index kAnchor: its own accessors, the storage's for every other index.
const uint kAnchor = 0xFFFFFFFEu;
uniform bool uAnyStored;  // whether the pass stored anything anywhere (else: anchors only)
uvec4 gAnchor;  // packed colour, object id + 1, primitive id
#define ANCHOR_OR(i, anchorValue, storedValue) ((i) == kAnchor ? (anchorValue) : (storedValue))
uint objectOf(uint i) { return ANCHOR_OR(i, gAnchor.z - 1u, fragmentObject(i)); }
uint primitiveOf(uint i) { return ANCHOR_OR(i, gAnchor.w, fragmentPrimitive(i)); }
float depthOf(uint i) { return ANCHOR_OR(i, 1.0, fragmentDepth(i)); }  // one per (object, primitive): never compared
void compositeAny(uint i, inout vec3 color, inout float transmittance) {
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
void compositeAny(uint i, inout vec3 color, inout float transmittance) { compositeFragment(i, color, transmittance); }
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
void compositeLayer(bool stored, inout vec3 color, inout float transmittance) {
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

layout(location = 0) out vec4 outFront;
#ifdef DUAL
layout(location = 1) out vec4 outBack;
#endif

vec4 compositeSide(ivec2 pixel, int side) {
    bool stored = selectSide(pixel, side);
#ifndef ANCHOR
    if (!stored) return vec4(0.0);
#endif
    vec3 color = vec3(0.0);
    float transmittance = 1.0;
    compositeLayer(stored, color, transmittance);
    return vec4(color, 1.0 - transmittance);
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
#ifdef DUAL
    outFront = compositeSide(pixel, 0);
    outBack = compositeSide(pixel, 1);
#elif defined(ANCHOR)
    gAnchor = texelFetch(uAnchor, pixel, 0);
    if (gAnchor.z == 0u) discard;  // no layer here (coincident fragments come with an anchor)
    if (!uAnyStored) {
        // Nothing coincided anywhere in this layer: f2b's blend, no storage read.
        vec4 c = vec4(unpackHalf2x16(gAnchor.x), unpackHalf2x16(gAnchor.y));
        outFront = vec4(c.rgb * c.a, c.a);
        return;
    }
    outFront = compositeSide(pixel, 0);
#else
    if (!selectSide(pixel, 0)) discard;
    outFront = compositeSide(pixel, 0);
#endif
}
