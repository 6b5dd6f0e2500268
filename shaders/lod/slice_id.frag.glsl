#version 450 core
// Hole-filling preprocessing: the contract's alpha test, then the slice's id (1 + layer-local
// peel * slices + slice) so the host can tell which slices show through another view's holes.
#include "lod/lod_bindings.h"
#include "common/impostor_accept.glsl"

layout(binding = BIND_SLICE_ATLAS) uniform sampler2DArray uAtlas;
uniform int uSlices;
uniform float uOverlap;
uniform int uPeels;

in vec2 vUv;
flat in int vLayer;
flat in int vSlice;

layout(location = 0) out uint outId;

void main() {
    int res = textureSize(uAtlas, 0).x;
    ivec2 texel = clamp(ivec2(vUv * float(res)), ivec2(0), ivec2(res - 1));
    vec4 value = texelFetch(uAtlas, ivec3(texel, vLayer), 0);
    if (!impostorAccepts(value.a, vSlice, uSlices, uOverlap)) discard;
    outId = uint(1 + (vLayer % uPeels) * uSlices + vSlice);
}
