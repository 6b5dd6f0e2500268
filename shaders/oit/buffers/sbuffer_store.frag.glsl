#version 450 core
// S-buffer (Vasilakis & Fudos 2012), both geometry passes of one program so they rasterize the
// same fragments:
//  pass 0 counts each pixel's fragments (atomicAdd on a per-pixel counter);
//  a compute prefix sum turns the counts, in place, into each pixel's region start;
//  pass 1 stores each fragment at atomicAdd(offset[pixel], 1): the offset walks through the
//  pixel's contiguous region, ending at the next region's start, which the resolve reads back.
// The entries array is sized exactly to the counted total, or to the largest band of rows when
// the total exceeds the device's storage block (the host then stores and resolves band by band,
// entries relative to uBase). uCapacity guards a single row larger than a block: those
// fragments are counted, never written out of bounds.
#include "surface.glsl"
#include "entry.glsl"
#include "oit/fragment_color.glsl"
#include "oit/subgroup_counter.glsl"

layout(early_fragment_tests) in;
layout(std430, binding = BIND_PIXEL_OFFSETS) coherent buffer PixelOffsets { uint offsets[]; };
layout(binding = BIND_COUNTERS, offset = 0) uniform atomic_uint uDropped;
uniform uint uWidth;
uniform uint uCapacity;
uniform uint uBase;  // first entry of the band of rows being stored (0 unless banded)
uniform int uPass;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    uint index = uint(pixel.y) * uWidth + uint(pixel.x);
    if (uPass == 0) {  // a uniform branch: the counting pass needs no colour
        atomicAdd(offsets[index], 1u);
        return;
    }
    // The colour before the per-fragment branch below (oit/fragment_color.glsl).
    uvec2 words = storedSurfaceColor().words;
    uint slot = atomicAdd(offsets[index], 1u) - uBase;
    if (slot >= uCapacity) { subgroupCounterIncrement(uDropped); return; }
    entries[slot] = makeEntry(gl_FragCoord.z, uObjectId, uint(gl_PrimitiveID), words);
}
