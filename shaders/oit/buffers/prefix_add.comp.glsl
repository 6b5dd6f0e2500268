#version 450 core
// Second half of the block scan: adds each block's scanned total to its elements. One work
// group per 512-element block, like the scan, so the group count stays within the dispatch
// limit (65535) up to 33M elements.
layout(local_size_x = 256) in;
layout(std430, binding = 0) buffer Data { uint data[]; };
layout(std430, binding = 1) buffer Sums { uint sums[]; };
uniform uint uCount;

const uint kBlock = 512u;

void main() {
    uint base = gl_WorkGroupID.x * kBlock + gl_LocalInvocationID.x;
    uint add = sums[gl_WorkGroupID.x];
    if (base < uCount) data[base] += add;
    if (base + 256u < uCount) data[base + 256u] += add;
}
