#version 450 core
// Present: a frame's linear RGB output to a region of the window, sRGB-encoded (the default
// framebuffer is written without GL_FRAMEBUFFER_SRGB, so the encoding happens here, exactly once).
// The texel under the fragment is gl_FragCoord - uOrigin, so a texture of the region's size fills
// a viewport at uOrigin: (0, 0) for the whole window, one eye's half for side-by-side stereo.
#include "bindings.h"
layout(binding = BIND_SOURCE) uniform sampler2D uLinearColor;
uniform ivec2 uOrigin;
out vec4 fragColor;

vec3 linearToSrgb(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

void main() {
    ivec2 size = textureSize(uLinearColor, 0);
    ivec2 p = ivec2(gl_FragCoord.xy) - uOrigin;
    if (any(lessThan(p, ivec2(0))) || any(greaterThanEqual(p, size))) {
        fragColor = vec4(0.0, 0.0, 0.0, 1.0);
        return;
    }
    fragColor = vec4(linearToSrgb(texelFetch(uLinearColor, p, 0).rgb), 1.0);
}
