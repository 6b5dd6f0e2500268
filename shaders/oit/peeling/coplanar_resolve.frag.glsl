#version 450 core
// f2b-2p / f2b-3p, end of a peel iteration, per pixel with fragments counted: the id-min
// fragment goes under the accumulation (front to back); the id-max one over the layer's far
// part (it lies behind every id still open); when the layer is done (two or fewer were left)
// the far part goes under the accumulation and the state moves to the next layer's anchor,
// else the state keeps the anchor and narrows the id range to (min, max).
// Partials and fragments as coplanar_layer.glsl keeps them (two texels each with
// STRATA_RGB_TRANSMITTANCE). Reads and writes its own texel of the accumulation, the far part
// and the state (a feedback loop GL allows for one read and one write per texel, after
// glTextureBarrier).
// Two draws an iteration share this shader. The first, straight after the counting pass, resolves
// the pixels whose layer holds one fragment left (its colour is the counting pass's sum) and
// tallies in atomic counters (subgroup_counter.glsl) those with one and those with two or more,
// which it leaves untouched. Only where that tally of two or more is not zero does the host
// extract and draw the second, COPLANAR_PIXELS, which resolves just those (and alone reads the
// id-max fragment and the state: the first's branches for them are compiled out, since llvmpipe
// runs every branch for every lane, masked). So where nothing is coplanar an iteration of f2b-2p
// is the counting pass and one full-screen pass (f2b-3p: its depth pass too); a separate
// full-screen check before the resolve cost f2b-2p 5.1 of 55.9 ms on builtin:layers:16 at
// 256x256 (llvmpipe).
// NO_OPEN_LAYER (first draw only): the build the host draws while no second draw has run this
//   frame, so no pixel has a layer's far part open: it neither reads nor writes that target
//   (the host masks it), which keeps its clear, the empty partial.
// NEXT_FROM_DEPTH (f2b-3p): the next anchor is the depth pass's, not the count target's b.
// BAND_OUT (f2b-3p): also writes the far edge of the state's layer as depth, what the band pass
//   (coplanar_band.frag.glsl) writes, so only the first iteration needs that pass. Where this
//   discards, the state and so the band stay as they were.
#include "coplanar_layer.glsl"
#ifndef COPLANAR_PIXELS
#include "bindings.h"
#include "oit/subgroup_counter.glsl"
#endif
#ifdef BAND_OUT
#include "layer_tie.glsl"
#endif

layout(binding = BIND_COPLANAR_COUNT) uniform sampler2D uCount;
layout(binding = BIND_COPLANAR_MIN_COLOR) uniform sampler2D uMinColor;
#ifdef COPLANAR_PIXELS
layout(binding = BIND_COPLANAR_STATE) uniform sampler2D uState;
layout(binding = BIND_COPLANAR_MAX_COLOR) uniform sampler2D uMaxColor;
#endif
layout(binding = BIND_COPLANAR_LAYER) uniform sampler2D uLayer;
layout(binding = BIND_COPLANAR_ACCUM) uniform sampler2D uAccum;
#ifdef NEXT_FROM_DEPTH
layout(binding = BIND_COPLANAR_NEXT_DEPTH) uniform sampler2D uNextDepth;
#endif
#ifndef COPLANAR_PIXELS
layout(binding = BIND_COUNTERS, offset = 0) uniform atomic_uint uCoplanarPixels;  // two or more left
layout(binding = BIND_COUNTERS, offset = 4) uniform atomic_uint uSinglePixels;    // exactly one left
#endif
layout(location = 0) out vec4 outAccum;
layout(location = 1) out vec4 outLayer;
layout(location = 2) out vec4 outState;
#ifdef STRATA_RGB_TRANSMITTANCE
layout(binding = BIND_COPLANAR_MIN_OPACITY) uniform sampler2D uMinOpacity;
#ifdef COPLANAR_PIXELS
layout(binding = BIND_COPLANAR_MAX_OPACITY) uniform sampler2D uMaxOpacity;
#endif
layout(binding = BIND_COPLANAR_LAYER_PASSES) uniform sampler2D uLayerPasses;
layout(binding = BIND_COPLANAR_ACCUM_PASSES) uniform sampler2D uAccumPasses;
layout(location = 3) out vec4 outAccumPasses;
layout(location = 4) out vec4 outLayerPasses;
#endif

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec4 count = texelFetch(uCount, pixel, 0);
#ifdef COPLANAR_PIXELS
    if (count.a < 1.5) discard;
#else
    bool coplanar = count.a > 1.5, single = count.a > 0.5 && !coplanar;
    subgroupCounterCount(uCoplanarPixels, coplanar);
    subgroupCounterCount(uSinglePixels, single);
    if (!single) discard;
#endif
    Partial accum = merged(FETCH_PARTIAL(uAccum, uAccumPasses, pixel), FETCH_FRAGMENT(uMinColor, uMinOpacity, pixel));
#ifdef NO_OPEN_LAYER
    Partial layer = kEmptyPartial;
#else
    Partial layer = FETCH_PARTIAL(uLayer, uLayerPasses, pixel);
#endif
    vec4 state;
#ifdef COPLANAR_PIXELS
    layer = merged(FETCH_FRAGMENT(uMaxColor, uMaxOpacity, pixel), layer);
    bool layerDone = count.a < 2.5;  // two were left, both taken now
    // Else the same anchor, the open id range narrowed to (min, max).
    if (!layerDone) state = vec4(texelFetch(uState, pixel, 0).r, -count.r, count.g, 0.0);
#else
    // The one fragment left. A build of its own, not a branch on the count: llvmpipe fetches
    // and merges in every branch for every lane.
    const bool layerDone = true;
#endif
    if (layerDone) {
        accum = merged(accum, layer);
        layer = kEmptyPartial;
#ifdef NEXT_FROM_DEPTH
        float next = texelFetch(uNextDepth, pixel, 0).r;
        state = vec4(next > 0.0 ? next : kNoAnchor, 0.0, kAllIds, 0.0);
#else
        state = vec4(hasAnchor(count.b) ? count.b : kNoAnchor, 0.0, kAllIds, 0.0);
#endif
    }
    outAccum = colorTexel(accum);
    outLayer = colorTexel(layer);
    outState = state;
#ifdef BAND_OUT
    gl_FragDepth = hasAnchor(state.r) ? layerFarEdge(state.r) : 1.0;
#endif
#ifdef STRATA_RGB_TRANSMITTANCE
    outAccumPasses = passesTexel(accum);
    outLayerPasses = passesTexel(layer);
#endif
}
