#version 450 core
// Weighted blended OIT (McGuire and Bavoil 2013), accumulation pass. Location 0 is blended
// additively (ONE, ONE): (premultiplied colour, alpha) times the depth weight w(z, alpha).
// Location 1 is blended with (ZERO, ONE_MINUS_SRC_COLOR): revealage *= (1 - alpha).
#include "surface.glsl"

STRATA_EARLY_TESTS_NO_SIDE_EFFECTS  // common/scene_prelude.glsl
layout(location = 0) out vec4 outAccum;
layout(location = 1) out vec4 outRevealage;

uniform float uNear;
uniform float uFar;
// WEIGHT_EQUATION: 7, 8, 9 (view depth) or 10 (window depth) of the paper; a program each, not
// a uniform: llvmpipe ran the uniform's branches as masked code.
#ifndef WEIGHT_EQUATION
#define WEIGHT_EQUATION 7
#endif
uniform float uWeightScale = 1.0;  // 1/16 in half float: keeps sums of weights up to 3e3 finite

// Eye distance from reversed-Z window depth: z_w = n (f - d) / (d (f - n))  =>  d = n f / (z_w (f - n) + n).
float viewDepth(float windowDepth) {
    return uNear * uFar / (windowDepth * (uFar - uNear) + uNear);
}

// Integer powers as products: pow() is exp2(log2()) per call, a third of this pass on llvmpipe.
float sq(float x) { return x * x; }
float cube(float x) { return x * x * x; }

float depthWeight(float alpha) {
#if WEIGHT_EQUATION == 10
    // The paper's d(z) is conventional window depth (0 near, 1 far): 1 - d = reversed-Z depth.
    return alpha * max(1e-2, 3e3 * cube(gl_FragCoord.z));
#else
    float z = viewDepth(gl_FragCoord.z);
#if WEIGHT_EQUATION == 8
    float w = 10.0 / (1e-5 + cube(z / 10.0) + cube(sq(z / 200.0)));
#elif WEIGHT_EQUATION == 9
    float w = 0.03 / (1e-5 + sq(sq(z / 200.0)));
#else
    float w = 10.0 / (1e-5 + sq(z / 5.0) + cube(sq(z / 200.0)));
#endif
    return alpha * clamp(w, 1e-2, 3e3);
#endif
}

void main() {
    vec4 c = surfaceColor();
    float w = depthWeight(c.a) * uWeightScale;
    outAccum = vec4(c.rgb * c.a, c.a) * w;
    outRevealage = vec4(c.a);
}
