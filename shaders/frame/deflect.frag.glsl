#version 450 core
// Image deflection and zoom enlargement in one pass (core/render/deflection_warp.hpp): each
// output pixel centre p, in GL window coordinates of the display (origin bottom-left corner, y up),
// maps to the display position d = uMap * (p, 1), the inverse map, which lies in source texel
// d / uZoom: the source is the frame drawn at 1/uZoom of the display's size (render/zoom.hpp), so
// with the identity map and nearest sampling this is pixel replication. Outside the display
// [0, W] x [0, H] (or behind, w <= 0) gives the border colour and counts.
#include "bindings.h"
layout(binding = BIND_SOURCE) uniform sampler2D uSource;
layout(binding = BIND_COUNTERS, offset = 0) uniform atomic_uint uOutside;
uniform mat3 uMap;
uniform int uBilinear;   // 0: nearest texel, 1: bilinear by hand
uniform int uCount;      // 1: count border pixels
uniform vec4 uBorder;
uniform int uZoom;          // display pixels per source texel, a side (1: same size)
uniform ivec2 uDisplaySize; // the display (output) size the map's pixels refer to
out vec4 fragColor;

vec4 fetchClamped(ivec2 t, ivec2 size) {
    return texelFetch(uSource, clamp(t, ivec2(0), size - 1), 0);
}

// One exit, no early returns: the nearest-sampled homography failed on NVIDIA while the same
// shader's bilinear path passed; this keeps the control flow the same for both filters.
void main() {
#ifdef REPLICATE
    // Zoom's plain enlargement (identity map, nearest): display pixel p shows texel p / z, every
    // pixel inside. Its own program, so the general map's per-pixel work is not paid for it.
    fragColor = texelFetch(uSource, ivec2(gl_FragCoord.xy) / uZoom, 0);
#else
    ivec2 size = textureSize(uSource, 0);
    vec3 h = uMap * vec3(gl_FragCoord.xy, 1.0);
    vec2 d = h.xy / h.z;
    // The negated test also sends NaN (a degenerate map) to the border.
    bool inside = h.z > 0.0 && all(greaterThanEqual(d, vec2(0.0))) && all(lessThanEqual(d, vec2(uDisplaySize)));
    // Display pixel centres (i + 0.5) never fall on a texel edge for an integer zoom, so floor()
    // below replicates exactly; the division is the only rounding and is far from those edges.
    vec2 s = d / float(uZoom);
    vec4 color = uBorder;
    if (!inside) {
        if (uCount != 0) atomicCounterIncrement(uOutside);
    } else if (uBilinear == 0) {
        // The texel whose square contains s; s == size on the far edges clamps to the last one.
        color = fetchClamped(ivec2(floor(s)), size);
    } else {
        // Texel centres sit at integer + 0.5: interpolate between the four around s with float
        // weights (hardware filtering rounds them to ~8 bits), edge texels repeated at the rim.
        vec2 t = s - 0.5;
        ivec2 i0 = ivec2(floor(t));
        vec2 f = t - vec2(i0);
        vec4 c00 = fetchClamped(i0, size);
        vec4 c10 = fetchClamped(i0 + ivec2(1, 0), size);
        vec4 c01 = fetchClamped(i0 + ivec2(0, 1), size);
        vec4 c11 = fetchClamped(i0 + ivec2(1, 1), size);
        color = mix(mix(c00, c10, f.x), mix(c01, c11, f.x), f.y);
    }
    fragColor = color;
#endif
}
