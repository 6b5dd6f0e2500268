// The store side of oit/packed_color.glsl: the current fragment's colour words, from
// common/surface.glsl. `c` is its surfaceColor(), which every store computes first (before any
// branch: a texture fetch takes derivatives) and hands the tail. With STRATA_RGB_TRANSMITTANCE a
// transmissive material's fragment stores its SurfaceOptics in the coloured filter's layout;
// every other fragment the scalar layout.
#include "oit/packed_color.glsl"

uvec2 packSurfaceColor(vec4 c) {
#if defined(STRATA_RGB_TRANSMITTANCE) && defined(STRATA_TRANSMISSION)
    if (uTransmission > 0.0) {
        SurfaceOptics o = surfaceOptics();
        return uvec2(packRgb9e5(o.premultiplied), packUnorm3x10(o.transmittance) | kColoredFilter);
    }
#endif
    return uvec2(packHalf2x16(c.rg), packHalf2x16(c.ba));
}
