// The "tail" of the bounded buffers, resolve side: the overflowed fragments as one layer with
// their alpha-weighted average colour and the coverage 1 - prod(1 - a), composited behind the
// sorted fragments. Exact when one fragment overflowed, approximate otherwise.
#include "oit/buffers/buffer_bindings.h"
#include "oit/transmittance.glsl"

layout(binding = BIND_TAIL_ACCUM) uniform sampler2D uTailAccum;
layout(binding = BIND_TAIL_REVEAL) uniform sampler2D uTailReveal;
uniform bool uTail;

void compositeTail(ivec2 pixel, inout vec3 color, inout Transmittance transmittance) {
    if (!uTail) return;
    vec4 accum = texelFetch(uTailAccum, pixel, 0);
    if (accum.a <= 0.0) return;
    float alpha = 1.0 - texelFetch(uTailReveal, pixel, 0).r;
    color += transmittance * alpha * (accum.rgb / accum.a);
    transmittance *= 1.0 - alpha;
}
