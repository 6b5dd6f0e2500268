#version 450 core
// A-buffer resolve as a compute dispatch over a tile (same result as abuffer_resolve.frag.glsl):
// one invocation per pixel, writing the output colour as an image. On GPUs whose fragment stage
// runs on a few units only (Hopper data-centre parts), compute uses them all.
#ifdef LIST_TAIL
#include "buffers/tail_resolve.glsl"
#endif
#ifdef VOLUME
#include "oit/volume/volume_list.glsl"
#else
#include "abuffer_list.glsl"
#endif

layout(local_size_x = RESOLVE_GROUP_SIZE, local_size_y = RESOLVE_GROUP_SIZE) in;

layout(binding = BIND_OPAQUE_COLOR) uniform sampler2D uOpaqueColor;
layout(binding = BIND_RESOLVE_OUTPUT, rgba32f) uniform writeonly image2D uOutput;
uniform ivec4 uTile;  // origin x, y and size w, h in pixels

void main() {
    ivec2 local = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(local, uTile.zw))) return;
    ivec2 pixel = uTile.xy + local;
    imageStore(uOutput, pixel, vec4(resolvePixel(pixel, texelFetch(uOpaqueColor, pixel, 0).rgb), 1.0));
}
