#version 450 core
// The one shared fragment count: every transparent fragment in front of the opaque depth
// (early depth test, no depth writes) increments one atomic counter. robustness_ratio of
// every technique divides by this number.
#include "bindings.h"
layout(early_fragment_tests) in;
layout(binding = BIND_COUNTERS, offset = 0) uniform atomic_uint uFragmentCount;

void main() {
    atomicCounterIncrement(uFragmentCount);
}
