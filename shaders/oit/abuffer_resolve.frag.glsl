#version 450 core
// A-buffer resolve as a full-screen fragment pass: composites each pixel's linked list over the
// opaque colour in the exact order of ordered_composite.glsl (depth, near-equal depths in
// object order). `ll` uses this resolve too, with LIST_TAIL defined: its overflowed fragments,
// blended into a tail layer, composite behind the sorted ones.
#ifdef LIST_TAIL
#include "buffers/tail_resolve.glsl"
#endif
#ifdef VOLUME
#include "oit/volume/volume_list.glsl"
#else
#include "abuffer_list.glsl"
#endif

layout(binding = BIND_OPAQUE_COLOR) uniform sampler2D uOpaqueColor;
layout(location = 0) out vec4 outColor;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    outColor = vec4(resolvePixel(pixel, texelFetch(uOpaqueColor, pixel, 0).rgb), 1.0);
}
