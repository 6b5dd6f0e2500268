#version 450 core
// Skip queries, step 2: a rectangle sample passes where the object could still have an
// unpeeled fragment, judged from the object's depth range over its whole bounding box
// (reversed-Z) and the block maxima of the bound (bound_reduce.frag.glsl).
// Bit 0 of uSides: what remains is not nearer than r (r <= 0: nothing left); live if the box's
// farthest depth is at or behind r. Bit 1: what remains is not farther than -g; live if the
// box's nearest depth is at or in front of -g. With both (dual), a sample passes only where the
// box's depth range meets the block's remaining range [-g, r] at that block, so one query
// answers for the object and one conditional draw can skip it exactly. Per block is
// conservative: the block's range holds each of its pixels' ranges.
#include "peel_bindings.h"

layout(binding = BIND_PEEL_PREVIOUS) uniform sampler2D uReducedBound;
uniform int uSides;
uniform float uBoxFar;   // smallest window depth of the box (its farthest point)
uniform float uBoxNear;  // largest window depth of the box (its nearest point)

void main() {
    vec2 bound = texelFetch(uReducedBound, ivec2(gl_FragCoord.xy), 0).rg;
    bool live = true;
    if ((uSides & 1) != 0) live = live && bound.r > 0.0 && uBoxFar <= bound.r;
    if ((uSides & 2) != 0) live = live && uBoxNear >= -bound.g;
    if (!live) discard;
}
