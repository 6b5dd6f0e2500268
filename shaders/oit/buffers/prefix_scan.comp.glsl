#version 450 core
// Work-efficient exclusive scan (Blelloch) of one block of 2 * local size elements per work
// group, in place; each group's total goes to sums[group]. Elements past uCount read as 0 and
// are not written, so any count works. The host scans `sums` the same way (recursively) and
// adds it back with prefix_add.comp.glsl.
#include "buffer_bindings.h"

layout(local_size_x = SCAN_GROUP_SIZE) in;
layout(std430, binding = BIND_SCAN_DATA) buffer Data { uint data[]; };
layout(std430, binding = BIND_SCAN_SUMS) buffer Sums { uint sums[]; };
uniform uint uCount;

shared uint temp[SCAN_BLOCK];

void main() {
    uint t = gl_LocalInvocationID.x;
    uint a = gl_WorkGroupID.x * SCAN_BLOCK + 2u * t;
    temp[2u * t] = a < uCount ? data[a] : 0u;
    temp[2u * t + 1u] = a + 1u < uCount ? data[a + 1u] : 0u;

    uint offset = 1u;
    for (uint d = SCAN_BLOCK >> 1; d > 0u; d >>= 1) {  // up-sweep: partial sums in a tree
        barrier();
        if (t < d) {
            uint ai = offset * (2u * t + 1u) - 1u;
            uint bi = offset * (2u * t + 2u) - 1u;
            temp[bi] += temp[ai];
        }
        offset <<= 1;
    }
    barrier();
    if (t == 0u) {
        sums[gl_WorkGroupID.x] = temp[SCAN_BLOCK - 1u];
        temp[SCAN_BLOCK - 1u] = 0u;
    }
    for (uint d = 1u; d < SCAN_BLOCK; d <<= 1) {  // down-sweep: exclusive prefixes
        offset >>= 1;
        barrier();
        if (t < d) {
            uint ai = offset * (2u * t + 1u) - 1u;
            uint bi = offset * (2u * t + 2u) - 1u;
            uint left = temp[ai];
            temp[ai] = temp[bi];
            temp[bi] += left;
        }
    }
    barrier();
    if (a < uCount) data[a] = temp[2u * t];
    if (a + 1u < uCount) data[a + 1u] = temp[2u * t + 1u];
}
