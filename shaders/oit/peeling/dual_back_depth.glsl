// dual's back depth test (the back_depth_test setting): the depth buffer a peel pass tests with
// GL_GEQUAL holds the back of its range, so the fragments behind it (back layers peeled already)
// are rejected before they are shaded. The value is 16 ulps farther than the back (reversed-Z:
// smaller), so that a fragment at the back itself passes whatever way the hardware rounds the
// depth it tests; the peel shader's own comparisons decide the fragments near it, as without
// the test. An empty range gets 1 (the near plane): nothing but fragments there pass, and the
// shader discards those.
float dualBackDepth(vec2 range) {
    if (range.r < -1.0) return 1.0;
    const float back = -range.g;
    return back > 0.0 ? intBitsToFloat(max(floatBitsToInt(back) - 16, 0)) : 0.0;
}
