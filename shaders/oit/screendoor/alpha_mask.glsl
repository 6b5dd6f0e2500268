// The random binary masks of the screen-door techniques (core/oit/screendoor/alpha_masks.*):
// layer l of the array keeps each texel with probability l / ALPHA_LEVELS. A fragment survives
// when the texel it lands on is set; the masks wrap (their side is a power of two).
#include "screendoor_bindings.h"
#include "random_hash.glsl"

layout(binding = BIND_ALPHA_MASKS) uniform usampler2DArray uAlphaMasks;
uniform uint uSeed;

int alphaLevel(float alpha) {
    return int(round(clamp(alpha, 0.0, 1.0) * float(ALPHA_LEVELS)));
}

bool maskKeeps(ivec2 texel, float alpha) {
    int side = textureSize(uAlphaMasks, 0).x;
    return texelFetch(uAlphaMasks, ivec3(texel & (side - 1), alphaLevel(alpha)), 0).r != 0u;
}

// Per-object and per-triangle mask offsets come from (seed, object, triangle), so they do not
// depend on the draw order.
ivec2 maskOffset(uint objectId, uint triangle) {
    uint h = hashUint(hashUint(hashUint(uSeed) ^ objectId) ^ triangle);
    return ivec2(int(h & 0xffffu), int(h >> 16));
}
