#version 450 core
// LOD cost calibration, the impostor side: the work an impostor slice does per pixel (the
// alpha test of lod-contract.md: fetch the texel, decode its depth code, keep it only in its
// slice's depth interval, shade the stored normal), so the measured cost per layer pixel is the
// one the impostor draw pays.
#include "common/bindings.h"

layout(binding = BIND_SOURCE) uniform sampler2DArray uAtlas;
uniform int uSlices;

in vec4 vSlice;
layout(location = 0) out vec4 outColor;

void main() {
    const ivec3 size = textureSize(uAtlas, 0);
    const ivec2 texelAt = clamp(ivec2(vSlice.xy * vec2(size.xy)), ivec2(0), size.xy - 1);
    const vec4 texel = texelFetch(uAtlas, ivec3(texelAt, int(vSlice.z)), 0);
    const int code = int(round(texel.a * 255.0));
    if (code == 0) discard;
    const float t = (float(code) - 0.5) / 255.0;
    if (min(int(t * float(uSlices)), uSlices - 1) != int(vSlice.w)) discard;
    const vec3 normal = normalize(texel.rgb * 2.0 - 1.0);
    outColor = vec4(vec3(0.1 + 0.8 * max(dot(normal, normalize(vec3(0.35, 0.8, 0.5))), 0.0)), 1.0);
}
