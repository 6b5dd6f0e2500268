#version 450 core
// The coplanarity detector's resolve (Vasilakis and Fudos, Fig. 13), over the A-buffer's lists of
// one tile: for each pixel, the largest number of transparent fragments in one depth layer under
// the exact reference's tie rule (depth_layer.glsl, the rule of core/render/depth_order.hpp).
// It writes that count with the pixel's fragment count (rg32ui), its Fig. 13 colour, and adds
// the pixel to the frame's totals.
//
// The layers are cut on the sorted sequence of keys, and equal keys always share a layer, so the
// result depends only on the multiset of depths: not on arrival order, nor on how ties between
// objects are ordered (which a composite needs and a count does not).
#include "oit/abuffer_storage.glsl"
#include "oit/depth_layer.glsl"
#include "oit/coplanarity_bindings.h"
#include "common/coplanarity_palette.glsl"

#define LOCAL_CAPACITY 64

layout(local_size_x = RESOLVE_GROUP_SIZE, local_size_y = RESOLVE_GROUP_SIZE) in;

layout(binding = BIND_LARGEST_LAYER, rg32ui) uniform writeonly uimage2D uLargestLayer;
layout(binding = BIND_RESOLVE_OUTPUT, rgba16f) uniform writeonly image2D uHeatmap;
layout(std430, binding = BIND_COPLANARITY_TOTALS) buffer CoplanarityTotals {
    uint totals[];
};
uniform ivec4 uTile;  // origin x, y and size w, h in pixels

uint gFirstNode;
// Links hold index + 1 with 0 ending the list, so "link - 1" ends at 0xFFFFFFFF.
#define FOR_EACH_FRAGMENT(i) for (uint i = gFirstNode; i != 0xFFFFFFFFu; i = nodes[i].next - 1u)

uint gLayers;     // layers of the pixel, set by the functions below
uint gFragments;  // fragments of the pixel, likewise

// Lists longer than the registers: walk the distinct keys nearest first by repeated selection,
// each with its multiplicity. O(n * distinct keys), exact for any depth complexity.
uint largestLayerLong() {
    uint largest = 0u, run = 0u;
    float previous = 0.0;
    bool first = true;
    while (true) {
        bool found = false;
        float key = 0.0;
        uint copies = 0u;
        FOR_EACH_FRAGMENT(i) {
            if (first) gFragments++;
            float k = layerKey(nodes[i].depth);
            if (!first && !(k < previous)) continue;
            if (!found || k > key) {
                key = k;
                copies = 1u;
                found = true;
            } else if (k == key) {
                copies++;
            }
        }
        if (!found) break;
        if (!first && sameLayer(previous, key)) {
            run += copies;
        } else {
            run = copies;
            gLayers++;
        }
        largest = max(largest, run);
        previous = key;
        first = false;
    }
    return largest;
}

uint largestLayer() {
    float key[LOCAL_CAPACITY];
    uint count = 0u;
    FOR_EACH_FRAGMENT(i) {
        if (count == LOCAL_CAPACITY) return largestLayerLong();
        key[count++] = layerKey(nodes[i].depth);
    }
    gFragments = count;
    // Insertion sort, nearest (largest key) first. Written as "if (!...) break" like
    // ordered_composite.glsl: llvmpipe miscompiled the "while (j > 0u && ...)" form there.
    for (uint a = 1u; a < count; ++a) {
        float k = key[a];
        uint j = a;
        while (j > 0u) {
            if (!(k > key[j - 1u])) break;
            key[j] = key[j - 1u];
            j--;
        }
        key[j] = k;
    }
    uint largest = 0u, run = 0u;
    for (uint a = 0u; a < count; ++a) {
        if (a > 0u && sameLayer(key[a - 1u], key[a])) {
            run++;
        } else {
            run = 1u;
            gLayers++;
        }
        largest = max(largest, run);
    }
    return largest;
}

void main() {
    ivec2 local = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(local, uTile.zw))) return;
    ivec2 pixel = uTile.xy + local;
    gFirstNode = imageLoad(uHeads, pixel).r - 1u;
    gLayers = 0u;
    gFragments = 0u;
    uint largest = largestLayer();
    imageStore(uLargestLayer, pixel, uvec4(largest, gFragments, 0u, 0u));
    imageStore(uHeatmap, pixel, vec4(coplanarityColor(largest), 1.0));
    atomicAdd(totals[min(largest, COPLANARITY_BINS - 1u)], 1u);
    if (gLayers > 0u) atomicAdd(totals[COPLANARITY_TOTAL_LAYERS], gLayers);
}
