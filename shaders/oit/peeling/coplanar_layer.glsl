// What the coplanarity-aware peeling variants (f2b-2p, f2b-3p, dual-2p) share: which layer a
// fragment is in and its id within the layer, both following the tie rule of
// core/render/depth_order.hpp (shared with every exact resolve through oit/depth_layer.glsl).
//
// Layer: a peel pass anchors a layer at the nearest remaining fragment (dual-2p's back side: the
// farthest); the layer is every remaining fragment within the tie tolerance of that anchor. The
// anchor is a max (min) over the fragment set and the window test is one expression, so the
// layers depend neither on arrival order nor on bit-equal depths. (The reference chains ties:
// three surfaces 0.6 tolerance apart are one layer there and two here. Only chains spread over
// more than the tolerance, 76 um at 10 m by default, can differ; round-off is a few ulps.)
//
// Id: the fragment's rank in the tie order, (object id, primitive id), as one number:
// idBase[object] (triangles of all lower objects, coplanar_ids.hpp) + gl_PrimitiveID. MAX
// blending needs floats, so the rank + 2^23 is stored as the bits of a positive normal float:
// positive floats order like their bits, MAX only selects, so ids up to 2^31 stay exact (a
// float value would be exact to 2^24 only). The host clears id channels to -FLT_MAX.
#ifndef STRATA_COPLANAR_LAYER_GLSL
#define STRATA_COPLANAR_LAYER_GLSL
#include "oit/depth_layer.glsl"
#include "oit/transmittance.glsl"
#include "peel_bindings.h"

const float kNoId = -3.402823466e38;  // -FLT_MAX: below every id and every negated id
const float kAllIds = 3.402823466e38; // open upper end of a fresh layer's id range (low end 0)
const float kNoAnchor = -1.0;         // no layer left on this side (the back side starts at 2)

bool hasAnchor(float anchor) { return anchor >= 0.0 && anchor <= 1.0; }

// z is in the layer anchored at `anchor` (a window depth, reversed-Z). Callers test the side
// (z <= anchor from the front, z >= anchor from the back) separately.
bool inLayerOf(float z, float anchor) { return sameLayer(layerKey(z), layerKey(anchor)); }

// dual-2p: which part of what is left z belongs to, given the front anchor (nearest left) and
// the back anchor (farthest left), either possibly none. The front layer wins where the two
// windows overlap, so a fragment is in one part only.
const int kPeeled = -1, kFrontLayer = 0, kBackLayer = 1, kBetween = 2;
int dualPart(float z, float front, float back) {
    bool hasFront = hasAnchor(front), hasBack = hasAnchor(back);
    if ((hasFront && z > front) || (hasBack && z < back) || (!hasFront && !hasBack)) return kPeeled;
    if (hasFront && inLayerOf(z, front)) return kFrontLayer;
    if (hasBack && inLayerOf(z, back)) return kBackLayer;
    // With one side closed, the other side's open layer holds everything left.
    return hasFront && hasBack ? kBetween : kPeeled;
}

// Compositing in partials: a run of fragments as its premultiplied colour and what it lets
// through, one value or, with STRATA_RGB_TRANSMITTANCE (a scene with coloured filters,
// oit/color_model.hpp), one per channel. In the targets a partial is one texel (colour,
// transmittance), or with STRATA_RGB_TRANSMITTANCE two: (colour, 1) and a "passes" texel
// (transmittance, 1).
struct Partial {
    vec3 color;
    Transmittance transmittance;
};
const Partial kEmptyPartial = Partial(vec3(0.0), Transmittance(1.0));
Partial merged(Partial front, Partial behind) {
    return Partial(front.color + front.transmittance * behind.color, front.transmittance * behind.transmittance);
}

// A fragment as the counting and extraction passes store it (coplanar_fragment.glsl), 0 for
// none in every channel, so that ADD sums and MAX selects over targets cleared to 0: (colour,
// alpha), or with STRATA_RGB_TRANSMITTANCE (premultiplied colour, 0) and an opacity texel
// (1 - transmittance per channel, 0). FETCH_FRAGMENT reads one, FETCH_PARTIAL a partial; the
// second sampler is only named in the RGB build.
#ifdef STRATA_RGB_TRANSMITTANCE
#define FETCH_FRAGMENT(colors, opacities, pixel) \
    Partial(texelFetch(colors, pixel, 0).rgb, 1.0 - texelFetch(opacities, pixel, 0).rgb)
#define FETCH_PARTIAL(colors, passes, pixel) Partial(texelFetch(colors, pixel, 0).rgb, texelFetch(passes, pixel, 0).rgb)
vec4 colorTexel(Partial p) { return vec4(p.color, 1.0); }
vec4 passesTexel(Partial p) { return vec4(p.transmittance, 1.0); }
#else
Partial fragmentPartial(vec4 fragment) { return Partial(fragment.a * fragment.rgb, 1.0 - fragment.a); }
#define FETCH_FRAGMENT(colors, opacities, pixel) fragmentPartial(texelFetch(colors, pixel, 0))
Partial partialOf(vec4 texel) { return Partial(texel.rgb, texel.a); }
#define FETCH_PARTIAL(colors, passes, pixel) partialOf(texelFetch(colors, pixel, 0))
vec4 colorTexel(Partial p) { return vec4(p.color, p.transmittance); }
#endif
#endif
