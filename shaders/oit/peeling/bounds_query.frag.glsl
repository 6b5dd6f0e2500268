#version 450 core
// Skip queries, step 2: a rectangle sample passes where the object could still have an
// unpeeled fragment, judged from the object's depth range over its whole bounding box
// (reversed-Z) and the block maxima of the bound (bound_reduce.frag.glsl).
// Side 0: what remains is not nearer than r (r <= 0: nothing left); live if the box's farthest
// depth is at or behind some r. Side 1: what remains is not farther than -g; live if the box's
// nearest depth is at or in front of some -g.
#include "peel_bindings.h"

layout(binding = BIND_PEEL_PREVIOUS) uniform sampler2D uReducedBound;
uniform int uSide;
uniform float uBoxFar;   // smallest window depth of the box (its farthest point)
uniform float uBoxNear;  // largest window depth of the box (its nearest point)

void main() {
    vec2 bound = texelFetch(uReducedBound, ivec2(gl_FragCoord.xy), 0).rg;
    bool live = uSide == 0 ? (bound.r > 0.0 && uBoxFar <= bound.r) : (uBoxNear >= -bound.g);
    if (!live) discard;
}
