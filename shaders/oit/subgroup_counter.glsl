// atomicCounterIncrement with one atomic per subgroup: the per-fragment counters of the store and
// count passes (the list stores' node counter; fab's, kbuffer's and the capture passes' tallies),
// and a tally of the invocations for which a condition holds (subgroupCounterCount).
// It returns what atomicCounterIncrement would: a value no other invocation gets, below the
// counter's final value, which is the number of invocations that called it. A pool too small
// still counts what it missed.
//
// With GL_ARB_shader_ballot (llvmpipe and NVIDIA have it), the active invocations of a subgroup
// share one atomic add: the lowest of them adds their number, and each takes its rank among them
// above what the add returned. llvmpipe runs every atomic lane by lane; the probe's list store lost
// 3 of its 14 ms this way, and Strata's 3-5 of 15-30 (results.md, "The lists beside the probe's,
// pass by pass"). Helper invocations take no part: their atomics have no effect, so one may not
// lead. Any control flow: the ballot sees only the invocations that reach the call.
// The #extension lines move to the top of the shader (gl/shader_program.cpp).
#ifndef STRATA_SUBGROUP_COUNTER_GLSL
#define STRATA_SUBGROUP_COUNTER_GLSL
#extension GL_ARB_shader_ballot : enable
#extension GL_ARB_gpu_shader_int64 : enable
#extension GL_ARB_shader_atomic_counter_ops : enable

#if defined(GL_ARB_shader_ballot) && defined(GL_ARB_gpu_shader_int64) && defined(GL_ARB_shader_atomic_counter_ops)
// The lowest lane set in a ballot (64 lanes at most); `lanes` must not be empty.
uint lowestLane(uvec2 lanes) { return lanes.x != 0u ? uint(findLSB(lanes.x)) : 32u + uint(findLSB(lanes.y)); }

uint subgroupCounterIncrement(atomic_uint counter) {
    const uvec2 lanes = unpackUint2x32(ballotARB(!gl_HelperInvocation));
    const uint leader = lowestLane(lanes);
    uint base = 0u;
    if (gl_SubGroupInvocationARB == leader)
        base = atomicCounterAddARB(counter, uint(bitCount(lanes.x) + bitCount(lanes.y)));
    base = readInvocationARB(base, leader);
    const uvec2 below = unpackUint2x32(packUint2x32(lanes) & gl_SubGroupLtMaskARB);
    return base + uint(bitCount(below.x) + bitCount(below.y));
}

// Adds the number of the subgroup's invocations whose `counted` is true, with one atomic (none
// when no invocation counts): a tally where nobody needs an index (dual's blend counts its layers
// this way). The lowest invocation that counts adds for all.
void subgroupCounterCount(atomic_uint counter, bool counted) {
    const uvec2 hits = unpackUint2x32(ballotARB(counted && !gl_HelperInvocation));
    if ((hits.x | hits.y) != 0u && gl_SubGroupInvocationARB == lowestLane(hits))
        atomicCounterAddARB(counter, uint(bitCount(hits.x) + bitCount(hits.y)));
}
#else
uint subgroupCounterIncrement(atomic_uint counter) { return atomicCounterIncrement(counter); }
void subgroupCounterCount(atomic_uint counter, bool counted) {
    if (counted) atomicCounterIncrement(counter);
}
#endif
#endif
