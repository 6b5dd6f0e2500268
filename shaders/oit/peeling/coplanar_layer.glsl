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

// Compositing in (premultiplied colour, transmittance) pairs; a fragment is (colour, alpha).
vec4 asPartial(vec4 fragment) { return vec4(fragment.a * fragment.rgb, 1.0 - fragment.a); }
vec4 merged(vec4 front, vec4 behind) { return vec4(front.rgb + front.a * behind.rgb, front.a * behind.a); }
const vec4 kEmptyPartial = vec4(0.0, 0.0, 0.0, 1.0);
#endif
