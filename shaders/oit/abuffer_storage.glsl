// The A-buffer's lists on the GPU: node pool and per-pixel heads, declared once for the store
// passes (abuffer, ll) and the resolves so their bindings and qualifiers cannot disagree.
#include "common/bindings.h"
#include "oit/abuffer_node.h"

layout(std430, binding = BIND_NODES) coherent buffer FragmentNodes {
    FragmentNode nodes[];
};

#ifdef HEADS_ARRAY
// Several lists per pixel, one per layer (bun-ll's depth buckets; FragmentLists::setHeadLayers).
layout(binding = BIND_HEADS, r32ui) uniform coherent uimage2DArray uHeads;
#else
layout(binding = BIND_HEADS, r32ui) uniform coherent uimage2D uHeads;
#endif
