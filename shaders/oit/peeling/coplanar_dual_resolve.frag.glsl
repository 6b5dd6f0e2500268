#version 450 core
// dual-2p, end of a peel iteration (see coplanar_resolve.frag.glsl for the front side). Back
// side, composited back to front: the id-max fragment (or the only one) goes over the back
// accumulation; the id-min one under the open back layer's near part, which goes over the back
// accumulation when that layer is done. A side whose layer is done moves to the next anchor
// from the fragments between (none: the side closes). Also writes the bound of what is left
// for the object skipper (r: nearest left, g: minus farthest left; -1 and -2 when nothing is).
// Own-texel reads of its attachments after glTextureBarrier; pixels with nothing counted on
// either side are discarded.
#include "coplanar_layer.glsl"

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
layout(location = 0) out vec4 outFrontAccum;
layout(location = 1) out vec4 outFrontLayer;
layout(location = 2) out vec4 outBackAccum;
layout(location = 3) out vec4 outBackLayer;
layout(location = 4) out vec4 outFrontState;
layout(location = 5) out vec4 outBackState;
layout(location = 6) out vec2 outBound;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec4 frontCount = texelFetch(uFrontCount, pixel, 0);
    vec4 backCount = texelFetch(uBackCount, pixel, 0);
    if (frontCount.a < 0.5 && backCount.a < 0.5) discard;
    vec4 frontState = texelFetch(uFrontState, pixel, 0);
    vec4 backState = texelFetch(uBackState, pixel, 0);

    vec4 frontAccum = texelFetch(uFrontAccum, pixel, 0);
    vec4 frontLayer = texelFetch(uFrontLayer, pixel, 0);
    if (frontCount.a > 0.5) frontAccum = merged(frontAccum, asPartial(texelFetch(uFrontMin, pixel, 0)));
    if (frontCount.a > 1.5) frontLayer = merged(asPartial(texelFetch(uFrontMax, pixel, 0)), frontLayer);
    if (frontCount.a < 2.5) {
        frontAccum = merged(frontAccum, frontLayer);
        frontLayer = kEmptyPartial;
        frontState = vec4(hasAnchor(frontCount.b) ? frontCount.b : kNoAnchor, 0.0, kAllIds, 0.0);
    } else {
        frontState = vec4(frontState.r, -frontCount.r, frontCount.g, 0.0);
    }

    vec4 backAccum = texelFetch(uBackAccum, pixel, 0);
    vec4 backLayer = texelFetch(uBackLayer, pixel, 0);
    if (backCount.a > 1.5) {
        backAccum = merged(asPartial(texelFetch(uBackMax, pixel, 0)), backAccum);
        backLayer = merged(backLayer, asPartial(texelFetch(uBackMin, pixel, 0)));
    } else if (backCount.a > 0.5) {
        backAccum = merged(asPartial(texelFetch(uBackMin, pixel, 0)), backAccum);  // the only one: its colour sum
    }
    if (backCount.a < 2.5) {
        backAccum = merged(backLayer, backAccum);
        backLayer = kEmptyPartial;
        backState = vec4(hasAnchor(-backCount.b) ? -backCount.b : kNoAnchor, 0.0, kAllIds, 0.0);
    } else {
        backState = vec4(backState.r, -backCount.r, backCount.g, 0.0);
    }

    bool front = hasAnchor(frontState.r), back = hasAnchor(backState.r);
    outBound = vec2(front ? frontState.r : (back ? 1.0 : -1.0), back ? -backState.r : (front ? 0.0 : -2.0));
    outFrontAccum = frontAccum;
    outFrontLayer = frontLayer;
    outBackAccum = backAccum;
    outBackLayer = backLayer;
    outFrontState = frontState;
    outBackState = backState;
}
