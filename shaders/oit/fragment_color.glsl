// The store side of oit/packed_color.glsl: the current fragment's colour words, from
// common/surface.glsl. `c` is its surfaceColor(), which every store computes first (before any
// branch: a texture fetch takes derivatives) and hands the tail; with
// STRATA_RGB_TRANSMITTANCE the words hold its SurfaceOptics instead.
#include "oit/packed_color.glsl"

uvec2 packSurfaceColor(vec4 c) {
#ifdef STRATA_RGB_TRANSMITTANCE
    SurfaceOptics o = surfaceOptics();
    return uvec2(packRgb9e5(o.premultiplied), packUnorm3x10(o.transmittance));
#else
    return uvec2(packHalf2x16(c.rg), packHalf2x16(c.ba));
#endif
}
