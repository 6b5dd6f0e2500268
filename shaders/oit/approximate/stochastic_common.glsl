// Stochastic transparency (Enderton et al. 2010) with S "virtual samples" per pixel: one layer
// of an r32ui array image per sample holds the depth bits of the nearest fragment that covered
// it. llvmpipe offers at most 4 MSAA samples, so samples are layers, not MSAA samples.
#include "surface.glsl"
#include "approximate_bindings.h"

uniform int uSamples;  // S, 1..64

// PCG hash (Jarzynski and Olano 2020, "Hash functions for GPU rendering").
uint pcgHash(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

// One seed per (pixel, primitive, object): both passes draw the same fragments and derive
// the same seed, so pass 1's coverage never needs storing.
uint fragmentSeed() {
    uvec2 pixel = uvec2(gl_FragCoord.xy);
    return pcgHash(pcgHash(pcgHash(pcgHash(pixel.x) + pixel.y) + uint(gl_PrimitiveID)) + uObjectId);
}

// Independent Bernoulli coverage: the fragment covers sample s with probability alpha.
bool coversSample(uint seed, int s, float alpha) {
    uint h = pcgHash(seed + uint(s) * 0x9E3779B9u);
    return float(h >> 8u) * (1.0 / 16777216.0) < alpha;
}

// Depth bits that order like reversed-Z depth: window depth is in [0, 1], non-negative, so its
// IEEE bits compare as unsigned integers in the same order ("nearer" = larger).
uint depthBits() { return floatBitsToUint(max(gl_FragCoord.z, 0.0)); }
