// The A-buffer's lists on the GPU: node pool and per-pixel heads, declared once for the store
// passes (abuffer, ll) and the resolves so their bindings and qualifiers cannot disagree.
#ifndef STRATA_ABUFFER_STORAGE_GLSL
#define STRATA_ABUFFER_STORAGE_GLSL
#include "common/bindings.h"
#include "oit/abuffer_node.h"

// A resolve built with NODE_TEXELS reads the pool through its buffer texture instead
// (oit/node_fetch.glsl) and declares no storage block: an unused coherent block stays active.
#ifndef NODE_TEXELS
layout(std430, binding = BIND_NODES) coherent buffer FragmentNodes {
    FragmentNode nodes[];
};
#endif

#ifdef HEADS_ARRAY
// Several lists per pixel, one per layer (bun-ll's depth buckets; FragmentLists::setHeadLayers).
layout(binding = BIND_HEADS, r32ui) uniform coherent uimage2DArray uHeads;
#else
layout(binding = BIND_HEADS, r32ui) uniform coherent uimage2D uHeads;
#endif

// Fills node `index` with one fragment (its colour words from oit/fragment_color.glsl) and links
// it in front of the list whose head is the value `head` was swapped out for: every store pass
// writes nodes this way. The caller swaps the head (imageAtomicExchange(uHeads, ..., index + 1u))
// and passes the old one.
#ifndef NODE_TEXELS
void writeNode(uint index, float depth, uint objectId, uint primitiveBits, uvec2 colorWords, uint head) {
    nodes[index].depth = depth;
    nodes[index].objectId = objectId;
    nodes[index].primitiveId = primitiveBits;
    nodes[index].colorRG = colorWords.x;
    nodes[index].colorBA = colorWords.y;
    nodes[index].next = head;
}
#endif
#endif
