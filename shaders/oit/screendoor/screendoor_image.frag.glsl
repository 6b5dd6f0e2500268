#version 450 core
// Image-space screen-door transparency (the classic stipple baseline): the mask of the
// fragment's alpha level is laid over the supersampled image, shifted by a random offset per
// object so that two objects of one alpha do not keep the same samples (Mulder et al.). A kept
// fragment is written opaque. Coverage per pixel is alpha whatever the surface's slope, so
// silhouettes are no more opaque than the rest (Sen et al. section 3). The level is the
// fragment's alpha: factor x texture x vertex colour.
#include "surface.glsl"
#include "alpha_mask.glsl"

uniform ivec2 uTileOriginSamples;

layout(location = 0) out vec4 outColor;

void main() {
    ivec2 sampleIndex = uTileOriginSamples + ivec2(gl_FragCoord.xy);
    vec4 c = surfaceColor();  // before the discard: a texture fetch takes derivatives
    if (!maskKeeps(sampleIndex + maskOffset(uObjectId, 0u), c.a)) discard;
    outColor = vec4(c.rgb, 1.0);
}
