#version 450 core
// Resolve of one peeled layer (f2b-ll, f2b-fab, f2b-kb; with DUAL the front and back layers of
// dual-ll, dual-fab): the pixel's stored fragments composite in the exact order of
// ordered_composite.glsl (coincident ones by object, then primitive), and the result goes out
// as (premultiplied colour, 1 - transmittance). The host blends output 0 under the front
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
#include "oit/ordered_composite.glsl"

layout(location = 0) out vec4 outFront;
#ifdef DUAL
layout(location = 1) out vec4 outBack;
#endif

vec4 compositeSide(ivec2 pixel, int side) {
    if (!selectSide(pixel, side)) return vec4(0.0);
    vec3 color = vec3(0.0);
    float transmittance = 1.0;
    compositeInDepthOrder(color, transmittance);
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
