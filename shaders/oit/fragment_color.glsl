// The store side of oit/packed_color.glsl: a fragment's colour words. Needs common/surface.glsl.
#include "oit/packed_color.glsl"

// The scalar layout of a colour and alpha (a surfaceColor()).
uvec2 packScalarColor(vec4 c) {
    return uvec2(packHalf2x16(c.rg), packHalf2x16(c.ba));
}

// What a store takes of the current fragment: its surfaceColor() (which the tail blends) and its
// colour words, shaded once. Stores call this first, before any branch (a texture fetch takes
// derivatives). With STRATA_RGB_TRANSMITTANCE a transmissive material's fragment stores its
// SurfaceOptics in the coloured filter's layout; every other fragment the scalar layout.
struct StoredColor {
    vec4 scalar;
    uvec2 words;
};

StoredColor storedSurfaceColor() {
#if defined(STRATA_RGB_TRANSMITTANCE) && defined(STRATA_TRANSMISSION)
    if (uTransmission > 0.0) {
        SurfaceOptics o = surfaceOptics();
        return StoredColor(scalarOpacityForm(o),
                           uvec2(packRgb9e5(o.premultiplied), packUnorm3x10(o.transmittance) | kColoredFilter));
    }
#endif
    vec4 c = surfaceColor();
    return StoredColor(c, packScalarColor(c));
}
