#version 450 core
// Crow's silhouette opacity (1978): the opacity grows from face-on to the rim as a power of the
// normal's component along the view direction. Crow writes the formula for the transmittance,
//   t = (tmax - tmin)(1 - (1 - |N_z|)^p) + tmin,
// so with alpha = 1 - t, amin = 1 - tmax (face-on) and amax = 1 - tmin (rim):
//   alpha = amax - (amax - amin)(1 - (1 - |N_z|)^p).
// N_z is taken against the direction to the eye at this fragment, not the view axis, so a sphere
// seen off-centre still reaches amax exactly at its silhouette under perspective.
// A textured or vertex-coloured material scales the result by its texel and vertex alpha (the
// fragment's alpha over the factor's), so a cut-out stays cut out.
// Blended "over" (SRC_ALPHA, ONE_MINUS_SRC_ALPHA), objects sorted back to front.
#include "surface.glsl"

uniform vec3 uEyePosition;
uniform float uAlphaMin;        // face-on opacity (ignored when uMaterialAlpha)
uniform float uAlphaMax;        // opacity at the silhouette
uniform float uPower;           // Crow's p
uniform bool uMaterialAlpha;    // face-on opacity is the material's alpha

layout(location = 0) out vec4 outColor;

float crowAlpha(float nz) {
    float amin = uMaterialAlpha ? uAlpha : uAlphaMin;
    float amax = max(uAlphaMax, amin);  // the rim is never more transparent than face-on
    return amax - (amax - amin) * (1.0 - pow(1.0 - nz, uPower));
}

void main() {
    vec3 n = normalize(surfaceNormal());
    vec3 toEye = normalize(uEyePosition - vWorldPosition);
    float nz = clamp(abs(dot(n, toEye)), 0.0, 1.0);
    vec4 c = surfaceColor();
    float texelAlpha = uAlpha > 0.0 ? c.a / uAlpha : 0.0;
    outColor = vec4(c.rgb, crowAlpha(nz) * texelAlpha);
}
