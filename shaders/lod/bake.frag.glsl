#version 450 core
// Impostor bake: one texel of the atlas per pixel, rgb = the object-space normal * 0.5 + 0.5,
// a = the depth code (1..255) of the surface kept by the depth test: the one FARTHEST from the
// apex (GL_GREATER, depth 0 at the slab's near plane), nearest a viewer on the view's side.
// PEEL: later peels keep the farthest surface strictly nearer the apex than the previous peel's
// (depth peeling towards the apex; the same triangle gives the same depth by GL's invariance).
#include "lod/lod_bindings.h"

in vec3 vObjectNormal;
in float vSlabT;

#ifdef PEEL
layout(binding = BIND_BAKE_PREVIOUS_DEPTH) uniform sampler2D uPreviousDepth;
#endif

layout(location = 0) out vec4 outTexel;

void main() {
#ifdef PEEL
    if (gl_FragCoord.z >= texelFetch(uPreviousDepth, ivec2(gl_FragCoord.xy), 0).r) discard;
#endif
    float codes = float(IMPOSTOR_DEPTH_CODES);
    float code = clamp(floor(clamp(vSlabT, 0.0, 1.0) * codes) + 1.0, 1.0, codes);
    float len = length(vObjectNormal);
    vec3 n = len > 0.0 ? vObjectNormal / len : vec3(0.0, 0.0, 1.0);
    outTexel = vec4(n * 0.5 + 0.5, code / 255.0);
}
