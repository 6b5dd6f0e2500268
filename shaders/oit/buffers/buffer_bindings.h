// What the buffer family's host code and shaders must agree on: binding points, the layout of
// one stored fragment, and the prefix scan's block size. The bindings start above the shared
// ones in common/bindings.h so a program may use both sets (ll: nodes and heads of the A-buffer).
#ifndef STRATA_BUFFER_BINDINGS_H
#define STRATA_BUFFER_BINDINGS_H
#include "common/host_device.h"

GPU_NAMESPACE_BEGIN

GPU_CONST uint BIND_ENTRIES = 2u;        // SSBO: FragmentEntry array (fab, kbuffer, sbuffer)
GPU_CONST uint BIND_PIXEL_OFFSETS = 3u;  // SSBO: sbuffer per-pixel counts, scanned in place to offsets
GPU_CONST uint BIND_DEPTH_KEYS = 4u;     // SSBO: kbuffer per-pixel sorted depth keys
GPU_CONST uint BIND_PIXEL_COUNTS = 1u;   // image unit: fab per-pixel counter (r32ui)
GPU_CONST uint BIND_TAIL_ACCUM = 2u;     // texture unit: tail sum(a*c), sum(a)
GPU_CONST uint BIND_TAIL_REVEAL = 3u;    // texture unit: tail prod(1-a)

// One stored fragment of the array-based buffers. Colour as two half2 pairs like the
// A-buffer's nodes, so quantisation stays far below 1/255 and the buffers can equal the
// reference.
struct FragmentEntry {
    float depth;       // window depth, reversed-Z: larger is nearer
    uint objectId;
    uint primitiveId;
    uint colorRG;      // packHalf2x16(r, g)
    uint colorBA;      // packHalf2x16(b, alpha)
};

// The prefix scan (sbuffer's offsets) runs alone, so it reuses SSBO points 0 and 1. Each group
// scans a block of two elements per invocation; the host sizes its block-total buffers by it.
GPU_CONST uint BIND_SCAN_DATA = 0u;
GPU_CONST uint BIND_SCAN_SUMS = 1u;
GPU_CONST uint SCAN_GROUP_SIZE = 256u;
GPU_CONST uint SCAN_BLOCK = 2u * SCAN_GROUP_SIZE;

GPU_NAMESPACE_END

#endif
