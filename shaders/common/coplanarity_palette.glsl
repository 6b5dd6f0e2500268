// Fig. 13's colour for a pixel's largest depth layer (common/coplanarity_palette.h), in linear
// RGB like every image the frame pipeline produces.
#include "common/coplanarity_palette.h"

const uint kCoplanarityPalette[COPLANARITY_PALETTE_SIZE] = uint[](COPLANARITY_PALETTE_SRGB);

// The sRGB transfer function's inverse, as core/image's srgbToLinear.
float coplanaritySrgbToLinear(float v) {
    return v <= 0.04045 ? v / 12.92 : pow((v + 0.055) / 1.055, 2.4);
}

vec3 coplanarityColor(uint largestLayer) {
    uint index = clamp(largestLayer, 1u, COPLANARITY_PALETTE_SIZE) - 1u;
    uint c = kCoplanarityPalette[index];
    vec3 srgb = vec3(float((c >> 16) & 0xFFu), float((c >> 8) & 0xFFu), float(c & 0xFFu)) / 255.0;
    return vec3(coplanaritySrgbToLinear(srgb.r), coplanaritySrgbToLinear(srgb.g), coplanaritySrgbToLinear(srgb.b));
}
