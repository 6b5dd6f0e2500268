#version 450 core
// Occlusion-query stage of object skipping: a box sample passes where the object could still
// have an unpeeled fragment. Side 0: the remaining fragments are not nearer than texel.r
// (reversed-Z, r <= 0 means nothing is left there); side 1: not farther than -texel.g.
// Any box sample at or beyond the bound means the box's far (near) face is, so the test is
// conservative for everything inside the box.
#include "peel_bindings.glsl"

layout(binding = BIND_PEEL_PREVIOUS) uniform sampler2D uRemaining;
uniform int uSide;

void main() {
    vec2 bound = texelFetch(uRemaining, ivec2(gl_FragCoord.xy), 0).rg;
    float z = gl_FragCoord.z;
    bool live = uSide == 0 ? (bound.r > 0.0 && z <= bound.r) : (z >= -bound.g);
    if (!live) discard;
}
