#version 450 core
// The one shared fragment count: every transparent fragment in front of the opaque depth
// (early depth test, no depth writes) increments one atomic counter, once per subgroup where the
// device can (oit/subgroup_counter.glsl). robustness_ratio of every technique divides by this
// number.
#include "bindings.h"
#include "oit/subgroup_counter.glsl"
layout(early_fragment_tests) in;
layout(binding = BIND_COUNTERS, offset = 0) uniform atomic_uint uFragmentCount;

void main() {
    subgroupCounterIncrement(uFragmentCount);
}
