#version 450 core
// Resolve of one peeled layer (f2b-ll, f2b-fab, f2b-kb; with DUAL the front and back layers of
// dual-ll, dual-fab): the pixel's stored fragments are one layer, so they composite in scene
// order (core/render/depth_order.hpp, step 3: object, then primitive), found by repeated
// selection: no sort arrays (a layer is one fragment but where surfaces coincide), O(n^2) in
// the coincident count, exact for any. The result goes out as (premultiplied colour,
// 1 - transmittance). The host blends output 0 under the front
// accumulation and, with DUAL, output 1 over the back accumulation. An empty side writes 0,
// neutral under both blends; without DUAL a pixel with nothing is discarded.
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

// Scene order; equal keys (one primitive cannot cover a pixel twice) fall back to the index so
// the order stays total.
bool sceneBefore(uint a, uint b) {
    uint oa = fragmentObject(a), ob = fragmentObject(b);
    if (oa != ob) return oa < ob;
    uint pa = fragmentPrimitive(a), pb = fragmentPrimitive(b);
    if (pa != pb) return pa < pb;
    float da = fragmentDepth(a), db = fragmentDepth(b);
    if (da != db) return da > db;
    return a < b;
}

void compositeLayer(inout vec3 color, inout float transmittance) {
    // Where nothing coincides (most pixels) the layer is one fragment: no selection.
    if (singleFragment()) {
        compositeFragment(gFirst, color, transmittance);
        return;
    }
    uint done = NO_FRAGMENT;
    while (true) {
        uint best = NO_FRAGMENT;
        FOR_EACH_FRAGMENT(i) {
            if (done != NO_FRAGMENT && !sceneBefore(done, i)) continue;
            if (best == NO_FRAGMENT || sceneBefore(i, best)) best = i;
        }
        if (best == NO_FRAGMENT) break;
        compositeFragment(best, color, transmittance);
        done = best;
    }
}

layout(location = 0) out vec4 outFront;
#ifdef DUAL
layout(location = 1) out vec4 outBack;
#endif

vec4 compositeSide(ivec2 pixel, int side) {
    if (!selectSide(pixel, side)) return vec4(0.0);
    vec3 color = vec3(0.0);
    float transmittance = 1.0;
    compositeLayer(color, transmittance);
    return vec4(color, 1.0 - transmittance);
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
#ifdef DUAL
    outFront = compositeSide(pixel, 0);
    outBack = compositeSide(pixel, 1);
#else
    if (!selectSide(pixel, 0)) discard;
    outFront = compositeSide(pixel, 0);
#endif
}
