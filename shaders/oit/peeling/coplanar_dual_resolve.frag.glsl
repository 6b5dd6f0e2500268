#version 450 core
// dual-2p, end of a peel iteration (see coplanar_resolve.frag.glsl for the front side). Back
// side, composited back to front: the id-max fragment (or the only one) goes over the back
// accumulation; the id-min one under the open back layer's near part, which goes over the back
// accumulation when that layer is done. A side whose layer is done moves to the next anchor
// from the fragments between (none: the side closes). Also writes the bound of what is left
// for the object skipper (r: nearest left, g: minus farthest left; -1 and -2 when nothing is).
// Own-texel reads of its attachments after glTextureBarrier; pixels with nothing counted on
// either side are discarded.
// One draw resolves both sides (seven targets). With STRATA_RGB_TRANSMITTANCE a partial takes
// two texels (coplanar_layer.glsl), more targets than the eight draw buffers GL guarantees, so
// the host draws the sides apart: RESOLVE_FRONT, then RESOLVE_BACK, which writes the bound from
// the front state the first draw left.
// ONE_PER_SIDE: the build the host draws when the check found no side holding two or more
// anywhere (no coplanarity: every iteration). It reads no id-max fragment and no state (a layer
// left open by an earlier iteration still closes). A build of its own, not a branch on the
// count: llvmpipe fetches and merges in every branch for every lane, masked.
// NO_OPEN_LAYER (with ONE_PER_SIDE): also no layer part open on either side, which holds until
// the frame's first iteration with two or more on a side: the build reads no layer part and
// the host masks those targets, which keep their clear, the empty partial.
#include "coplanar_layer.glsl"

#ifdef NO_OPEN_LAYER
#define FETCH_LAYER_PART(colors, passes, pixel) kEmptyPartial
#else
#define FETCH_LAYER_PART(colors, passes, pixel) FETCH_PARTIAL(colors, passes, pixel)
#endif

// Whether more than the two this iteration takes were left on a side: its layer stays open.
#ifdef ONE_PER_SIDE
#define MORE_LEFT(count) false
#else
#define MORE_LEFT(count) ((count).a > 2.5)
#endif

#if !defined(RESOLVE_FRONT) && !defined(RESOLVE_BACK)
#define RESOLVE_FRONT
#define RESOLVE_BACK
#define BOTH_SIDES
#endif

#define BACK(unit) ((unit) + BIND_COPLANAR_BACK_OFFSET)
layout(binding = BIND_COPLANAR_STATE) uniform sampler2D uFrontState;
layout(binding = BACK(BIND_COPLANAR_STATE)) uniform sampler2D uBackState;
layout(binding = BIND_COPLANAR_COUNT) uniform sampler2D uFrontCount;
layout(binding = BACK(BIND_COPLANAR_COUNT)) uniform sampler2D uBackCount;
layout(binding = BIND_COPLANAR_MIN_COLOR) uniform sampler2D uFrontMin;
layout(binding = BACK(BIND_COPLANAR_MIN_COLOR)) uniform sampler2D uBackMin;
layout(binding = BIND_COPLANAR_MAX_COLOR) uniform sampler2D uFrontMax;
layout(binding = BACK(BIND_COPLANAR_MAX_COLOR)) uniform sampler2D uBackMax;
layout(binding = BIND_COPLANAR_LAYER) uniform sampler2D uFrontLayer;
layout(binding = BACK(BIND_COPLANAR_LAYER)) uniform sampler2D uBackLayer;
layout(binding = BIND_COPLANAR_ACCUM) uniform sampler2D uFrontAccum;
layout(binding = BACK(BIND_COPLANAR_ACCUM)) uniform sampler2D uBackAccum;
#ifdef STRATA_RGB_TRANSMITTANCE
layout(binding = BIND_COPLANAR_MIN_OPACITY) uniform sampler2D uFrontMinOpacity;
layout(binding = BACK(BIND_COPLANAR_MIN_OPACITY)) uniform sampler2D uBackMinOpacity;
layout(binding = BIND_COPLANAR_MAX_OPACITY) uniform sampler2D uFrontMaxOpacity;
layout(binding = BACK(BIND_COPLANAR_MAX_OPACITY)) uniform sampler2D uBackMaxOpacity;
layout(binding = BIND_COPLANAR_LAYER_PASSES) uniform sampler2D uFrontLayerPasses;
layout(binding = BACK(BIND_COPLANAR_LAYER_PASSES)) uniform sampler2D uBackLayerPasses;
layout(binding = BIND_COPLANAR_ACCUM_PASSES) uniform sampler2D uFrontAccumPasses;
layout(binding = BACK(BIND_COPLANAR_ACCUM_PASSES)) uniform sampler2D uBackAccumPasses;
#endif

#ifdef BOTH_SIDES
layout(location = 0) out vec4 outFrontAccum;
layout(location = 1) out vec4 outFrontLayer;
layout(location = 2) out vec4 outBackAccum;
layout(location = 3) out vec4 outBackLayer;
layout(location = 4) out vec4 outFrontState;
layout(location = 5) out vec4 outBackState;
layout(location = 6) out vec2 outBound;
#else
layout(location = 0) out vec4 outAccum;
layout(location = 1) out vec4 outLayer;
layout(location = 2) out vec4 outState;
layout(location = 3) out vec4 outAccumPasses;  // the split draws are the RGB build's
layout(location = 4) out vec4 outLayerPasses;
#ifdef RESOLVE_BACK
layout(location = 5) out vec2 outBound;
#endif
#endif

struct Side {
    Partial accum;
    Partial layer;  // the open layer's far (front side) or near (back side) part
    vec4 state;
};

Side resolveFront(ivec2 pixel, vec4 count) {
    Side s = Side(FETCH_PARTIAL(uFrontAccum, uFrontAccumPasses, pixel),
                  FETCH_LAYER_PART(uFrontLayer, uFrontLayerPasses, pixel), vec4(0.0));
    if (count.a > 0.5) s.accum = merged(s.accum, FETCH_FRAGMENT(uFrontMin, uFrontMinOpacity, pixel));
#ifndef ONE_PER_SIDE
    if (count.a > 1.5) s.layer = merged(FETCH_FRAGMENT(uFrontMax, uFrontMaxOpacity, pixel), s.layer);
    if (MORE_LEFT(count)) s.state = vec4(texelFetch(uFrontState, pixel, 0).r, -count.r, count.g, 0.0);
#endif
    if (!MORE_LEFT(count)) {
        s.accum = merged(s.accum, s.layer);
        s.layer = kEmptyPartial;
        s.state = vec4(hasAnchor(count.b) ? count.b : kNoAnchor, 0.0, kAllIds, 0.0);
    }
    return s;
}

Side resolveBack(ivec2 pixel, vec4 count) {
    Side s = Side(FETCH_PARTIAL(uBackAccum, uBackAccumPasses, pixel),
                  FETCH_LAYER_PART(uBackLayer, uBackLayerPasses, pixel), vec4(0.0));
#ifndef ONE_PER_SIDE
    if (count.a > 1.5) {
        s.accum = merged(FETCH_FRAGMENT(uBackMax, uBackMaxOpacity, pixel), s.accum);
        s.layer = merged(s.layer, FETCH_FRAGMENT(uBackMin, uBackMinOpacity, pixel));
    } else
#endif
    if (count.a > 0.5) {
        // The only one: its colour sum.
        s.accum = merged(FETCH_FRAGMENT(uBackMin, uBackMinOpacity, pixel), s.accum);
    }
#ifndef ONE_PER_SIDE
    if (MORE_LEFT(count)) s.state = vec4(texelFetch(uBackState, pixel, 0).r, -count.r, count.g, 0.0);
#endif
    if (!MORE_LEFT(count)) {
        s.accum = merged(s.layer, s.accum);
        s.layer = kEmptyPartial;
        s.state = vec4(hasAnchor(-count.b) ? -count.b : kNoAnchor, 0.0, kAllIds, 0.0);
    }
    return s;
}

vec2 boundOfWhatIsLeft(vec4 frontState, vec4 backState) {
    bool front = hasAnchor(frontState.r), back = hasAnchor(backState.r);
    return vec2(front ? frontState.r : (back ? 1.0 : -1.0), back ? -backState.r : (front ? 0.0 : -2.0));
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec4 frontCount = texelFetch(uFrontCount, pixel, 0);
    vec4 backCount = texelFetch(uBackCount, pixel, 0);
    if (frontCount.a < 0.5 && backCount.a < 0.5) discard;
#ifdef BOTH_SIDES
    Side front = resolveFront(pixel, frontCount);
    Side back = resolveBack(pixel, backCount);
    outBound = boundOfWhatIsLeft(front.state, back.state);
    outFrontAccum = colorTexel(front.accum);
    outFrontLayer = colorTexel(front.layer);
    outBackAccum = colorTexel(back.accum);
    outBackLayer = colorTexel(back.layer);
    outFrontState = front.state;
    outBackState = back.state;
#else
#ifdef RESOLVE_FRONT
    Side side = resolveFront(pixel, frontCount);
#else
    Side side = resolveBack(pixel, backCount);
    outBound = boundOfWhatIsLeft(texelFetch(uFrontState, pixel, 0), side.state);  // the front draw's
#endif
    outAccum = colorTexel(side.accum);
    outLayer = colorTexel(side.layer);
    outState = side.state;
    outAccumPasses = passesTexel(side.accum);
    outLayerPasses = passesTexel(side.layer);
#endif
}
