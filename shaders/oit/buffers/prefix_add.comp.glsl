#version 450 core
// Second half of the block scan: adds each block's scanned total to its elements. One work
// group per SCAN_BLOCK-element block, like the scan, so the group count stays within the dispatch
// limit (65535) up to 33M elements.
#include "buffer_bindings.h"

layout(local_size_x = SCAN_GROUP_SIZE) in;
layout(std430, binding = BIND_SCAN_DATA) buffer Data { uint data[]; };
layout(std430, binding = BIND_SCAN_SUMS) buffer Sums { uint sums[]; };
uniform uint uCount;

void main() {
    uint base = gl_WorkGroupID.x * SCAN_BLOCK + gl_LocalInvocationID.x;
    uint add = sums[gl_WorkGroupID.x];
    if (base < uCount) data[base] += add;
    if (base + SCAN_GROUP_SIZE < uCount) data[base + SCAN_GROUP_SIZE] += add;
}
