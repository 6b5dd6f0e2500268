// One node index per fragment from a global atomic counter: the list stores' allocator (abuffer,
// ll, bun-ll). The counter's final value is the number of fragments that asked, as with one
// atomicCounterIncrement each, so a pool too small still counts what it missed.
//
// With GL_ARB_shader_ballot (llvmpipe and NVIDIA have it), the invocations of a subgroup take
// their indices with one atomic add: the lowest of them adds the subgroup's count and each takes
// its rank below it. llvmpipe runs every atomic lane by lane, and the probe's store in
// results.md ("The lists beside the probe's, pass by pass") lost 3 of its 14 ms this way.
// Helper invocations take no part: their atomics have no effect, so one may not lead.
// The #extension lines move to the top of the shader (gl/shader_program.cpp).
#extension GL_ARB_shader_ballot : enable
#extension GL_ARB_gpu_shader_int64 : enable
#extension GL_ARB_shader_atomic_counter_ops : enable

#if defined(GL_ARB_shader_ballot) && defined(GL_ARB_gpu_shader_int64) && defined(GL_ARB_shader_atomic_counter_ops)
// Call in uniform control flow (every invocation of the draw that reached the store).
uint claimNode(atomic_uint counter) {
    const uvec2 lanes = unpackUint2x32(ballotARB(!gl_HelperInvocation));
    const uint leader = lanes.x != 0u ? uint(findLSB(lanes.x)) : 32u + uint(findLSB(lanes.y));
    uint base = 0u;
    if (gl_SubGroupInvocationARB == leader)
        base = atomicCounterAddARB(counter, uint(bitCount(lanes.x) + bitCount(lanes.y)));
    base = readInvocationARB(base, leader);
    const uvec2 below = unpackUint2x32(packUint2x32(lanes) & gl_SubGroupLtMaskARB);
    return base + uint(bitCount(below.x) + bitCount(below.y));
}
#else
uint claimNode(atomic_uint counter) { return atomicCounterIncrement(counter); }
#endif
