// Per-pixel storage of one peeled layer's fragments, per side (0: the front layer; 1: dual's
// back layer, whose heads or counts sit uHeight rows below the front's), in one of three forms
// the host picks by define (core/oit/peeling/layer_storage.hpp):
//  LAYER_LIST: linked lists in one node pool (the A-buffer's nodes and heads); the front side
//              allocates from the pool's start, the back side from its end (section 3.1.3).
//  LAYER_FAB:  K entries per pixel and side with a per-pixel counter: the first K to arrive.
//  LAYER_KB:   K slots per pixel and side claimed in order by compare-and-swap (Algorithm 3's
//              k-buffer): the first K to arrive, no counter.
#include "bindings.h"
#if defined(LAYER_LIST)
#include "oit/abuffer_storage.glsl"
#elif defined(LAYER_FAB) || defined(LAYER_KB)
#include "oit/buffers/entry.glsl"
#if defined(LAYER_FAB)
layout(binding = BIND_PIXEL_COUNTS, r32ui) uniform coherent uimage2D uCounts;
#endif
#else
#error "define LAYER_LIST, LAYER_FAB or LAYER_KB"
#endif

uniform uint uWidth;     // frame width in pixels
uniform int uHeight;     // frame height: the back side's rows start here
uniform uint uCapacity;  // LAYER_LIST: nodes in the pool; else K per pixel and side

const uint kUnclaimed = 0xFFFFFFFFu;  // LAYER_KB: a free slot's object id

ivec2 sidePixel(ivec2 pixel, int side) { return pixel + ivec2(0, side * uHeight); }

// LAYER_FAB, LAYER_KB: the first of the K entries of a pixel's side.
uint firstEntry(ivec2 pixel, int side) {
    ivec2 p = sidePixel(pixel, side);
    return (uint(p.y) * uWidth + uint(p.x)) * uCapacity;
}
