#version 450 core
// Dual depth peeling pass (Bavoil and Myers 2008), reversed-Z. The previous pass left the
// nearest (r) and minus the farthest (g) depth of what remains. A fragment outside that range
// was peeled already; one strictly inside feeds the next range; one at the nearest depth is the
// front layer, one at the farthest the back layer. When only one fragment is left the two
// depths are equal and it goes to the front only, so it is counted once. All three targets use
// MAX blending: -2 and 0 are neutral, and colours carry alpha + 1 so that presence is visible.
// Nothing is counted here: an atomic per fragment per pass is a large share of a pass. The blend
// pass counts the pixels whose next range is not empty, once per pixel.
//
// STRATA_DUAL_ATOMIC_RANGE (the atomic_range setting): a fragment strictly inside the range
// leaves its depth bits in two r32i images by atomic max and min (depths are >= 0, so their bits
// order as the floats do) and is discarded, so only the two layers' fragments reach the blend
// units; dual_range_pack.frag.glsl turns the images into the next range. On a GPU with few
// blending units the MAX blend of every remaining fragment into three targets is what a pass
// costs (docs/gpu-h200-session5.md).
#include "surface.glsl"
#include "peel_bindings.h"

#ifdef STRATA_DUAL_ATOMIC_RANGE
// The atomics are side effects, which would make the depth test late: every fragment behind
// the opaque surfaces would run this shader. They lie outside every range (the init pass tests
// them), so testing early saves work; a wrapped variant discards before the atomics too.
layout(early_fragment_tests) in;
#include "dual_range_images.glsl"
#else
STRATA_EARLY_TESTS_NO_SIDE_EFFECTS  // common/scene_prelude.glsl
#endif
layout(binding = BIND_PEEL_PREVIOUS) uniform sampler2D uMinMax;

layout(location = 0) out vec2 outMinMax;
layout(location = 1) out vec4 outFront;
layout(location = 2) out vec4 outBack;
#ifdef STRATA_RGB_TRANSMITTANCE
// What the front and back layers let through per channel; 0 is neutral under MAX, and the
// colour targets' alpha says whether a layer is present.
layout(location = 3) out vec4 outFrontFilter;
layout(location = 4) out vec4 outBackFilter;
#endif

void main() {
    vec2 range = texelFetch(uMinMax, ivec2(gl_FragCoord.xy), 0).rg;
    float nearest = range.r;
    float farthest = -range.g;
    float z = gl_FragCoord.z;
    if (z > nearest || z < farthest) discard;
    outMinMax = vec2(-2.0);
    outFront = vec4(0.0);
    outBack = vec4(0.0);
#ifdef STRATA_RGB_TRANSMITTANCE
    outFrontFilter = vec4(0.0);
    outBackFilter = vec4(0.0);
#endif
    if (z < nearest && z > farthest) {
#ifdef STRATA_DUAL_ATOMIC_RANGE
        addToNextRange(z);
        discard;
#else
        outMinMax = vec2(z, -z);
        return;
#endif
    }
#ifdef STRATA_RGB_TRANSMITTANCE
    // Premultiplied colour, presence marked by alpha 2.
    SurfaceOptics o = surfaceOptics();
    if (z == nearest) {
        outFront = vec4(o.premultiplied, 2.0);
        outFrontFilter = vec4(o.transmittance, 0.0);
    } else {
        outBack = vec4(o.premultiplied, 2.0);
        outBackFilter = vec4(o.transmittance, 0.0);
    }
    return;
#endif
    vec4 c = surfaceColor();
    if (z == nearest)
        outFront = vec4(c.rgb, c.a + 1.0);
    else
        outBack = vec4(c.rgb, c.a + 1.0);
}
