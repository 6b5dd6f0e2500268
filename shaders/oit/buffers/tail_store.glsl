// The "tail" of the bounded buffers, store side. A fragment that does not fit is blended
// approximately instead of being dropped: location 0 accumulates (a*c, a) additively and
// location 1 the product of (1 - a) (blend GL_ZERO, GL_ONE_MINUS_SRC_COLOR). The resolve turns
// them into one weighted-average layer behind the stored ones (tail_resolve.glsl). A fragment
// that was stored writes the neutral values; with the tail off the colour writes are masked.
layout(location = 0) out vec4 outTailAccum;
layout(location = 1) out vec4 outTailReveal;

void tailNone() {
    outTailAccum = vec4(0.0);
    outTailReveal = vec4(0.0);
}

void tailAdd(vec4 c) {
    outTailAccum = vec4(c.a * c.rgb, c.a);
    outTailReveal = vec4(c.a);
}
