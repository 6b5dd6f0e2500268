// A per-pixel linked-list node of the exact A-buffer (and of ll's fixed pool); the host sizes
// the pool by sizeof(FragmentNode). Colour as two half2 pairs, not rgba8, so quantisation stays
// far below 1/255.
#ifndef STRATA_ABUFFER_NODE_H
#define STRATA_ABUFFER_NODE_H
#include "common/host_device.h"

GPU_NAMESPACE_BEGIN

// Texture unit: the same pool as an RGB32UI buffer texture, two texels a node (next, depth,
// objectId | primitiveId, colorRG, colorBA), for the resolves built with NODE_TEXELS
// (oit/node_fetch.glsl).
GPU_CONST uint BIND_NODE_TEXELS = 5u;

struct FragmentNode {
    uint next;        // index + 1 of the next node; 0 ends the list
    float depth;      // window depth, reversed-Z: larger is nearer
    uint objectId;
    uint primitiveId;
    uint colorRG;     // packHalf2x16(r, g)
    uint colorBA;     // packHalf2x16(b, alpha)
};

GPU_NAMESPACE_END

#endif
