// "The next layer" of the coplanarity-aware peeling variants (f2b-ll, f2b-fab, f2b-kb, dual-ll,
// dual-fab) under the project's tie rule (core/render/depth_order.hpp): a layer is the remaining
// fragments whose depth lies within the tie tolerance of the nearest (or, for dual's back layer,
// the farthest) remaining depth. Coincident surfaces, bit-equal or off by round-off, so fall in
// one layer and are all captured together; nothing depends on bit-equal depths.
#include "oit/depth_layer.glsl"

// Whether window depth z is in the layer anchored at window depth `layer`.
bool inLayer(float z, float layer) { return sameLayer(layerKey(z), layerKey(layer)); }

// Whether z was peeled by the pass whose layer was anchored at `layer`: in it, or nearer.
bool peeledWith(float z, float layer) {
    float k = layerKey(z), l = layerKey(layer);
    return k >= l || sameLayer(k, l);
}

// A window depth at or below the farthest depth of the layer anchored at `layer` (its band's far
// edge), lowered by a relative 1e-6 of the key against rounding: a depth test against it lets
// every fragment of the layer through, and the exact test above decides. (The margin is taken
// in key space: near the far plane a window depth's own 1e-6 is below the rounding of z + offset.)
float layerFarEdge(float layer) {
    return max(0.0, layerKey(layer) * (1.0 - uTieTolerance) * (1.0 - 1e-6) - uDepthOffset);
}
