// The random binary masks of the screen-door techniques (core/oit/screendoor/alpha_masks.*):
// layer l of the array keeps each texel with probability l / ALPHA_LEVELS. A fragment survives
// when the texel it lands on is set; the masks wrap (their side is a power of two).
#include "screendoor_bindings.h"

layout(binding = BIND_ALPHA_MASKS) uniform usampler2DArray uAlphaMasks;
uniform uint uSeed;

int alphaLevel(float alpha) {
    return int(round(clamp(alpha, 0.0, 1.0) * float(ALPHA_LEVELS)));
}

bool maskKeeps(ivec2 texel, float alpha) {
    int side = textureSize(uAlphaMasks, 0).x;
    return texelFetch(uAlphaMasks, ivec3(texel & (side - 1), alphaLevel(alpha)), 0).r != 0u;
}

// A well-mixed 32-bit hash (lowbias32, Wellons) of a key: per-object and per-triangle mask
// offsets come from (seed, object, triangle), so they do not depend on the draw order.
uint hashUint(uint x) {
    x ^= x >> 16; x *= 0x7feb352du;
    x ^= x >> 15; x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

ivec2 maskOffset(uint objectId, uint triangle) {
    uint h = hashUint(hashUint(hashUint(uSeed) ^ objectId) ^ triangle);
    return ivec2(int(h & 0xffffu), int(h >> 16));
}
