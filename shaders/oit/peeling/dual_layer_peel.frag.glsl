#version 450 core
// Peel pass of the coplanarity-aware dual variants (dual-ll, dual-fab), reversed-Z. The
// previous pass left the nearest (r) and minus the farthest (g) remaining depth. A fragment
// outside that range was peeled already; one in the front layer (within the tie tolerance of
// the nearest depth) is stored on side 0, one in the back layer (of the farthest) on side 1;
// when the two layers are one, it goes to the front only, so it is stored once. The rest feed
// the next range by MAX blending ((z, -z); -2 is neutral).
#include "surface.glsl"
#include "peel_bindings.h"
#include "layer_tie.glsl"
#include "layer_store.glsl"

STRATA_EARLY_TESTS_NO_SIDE_EFFECTS  // common/scene_prelude.glsl
layout(binding = BIND_PEEL_PREVIOUS) uniform sampler2D uMinMax;
layout(location = 0) out vec2 outMinMax;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec2 range = texelFetch(uMinMax, pixel, 0).rg;
    float nearest = range.r;
    float farthest = -range.g;
    float z = gl_FragCoord.z;
    outMinMax = vec2(-2.0);
    if (z > nearest || z < farthest) return;
    int side = inLayer(z, nearest) ? 0 : (inLayer(z, farthest) ? 1 : -1);
    if (side < 0) {
        outMinMax = vec2(z, -z);
        return;
    }
    storeLayerFragment(pixel, side, storedSurfaceColor().words);
}
