// What the coplanarity-aware variants' counting and extraction passes store of the current
// fragment (coplanar_layer.glsl: FETCH_FRAGMENT reads it back): its surfaceColor(), or with
// STRATA_RGB_TRANSMITTANCE its premultiplied colour and its opacity per channel. Needs
// common/surface.glsl.
#ifndef STRATA_COPLANAR_FRAGMENT_GLSL
#define STRATA_COPLANAR_FRAGMENT_GLSL
struct FragmentTexels {
    vec4 color;
    vec4 opacity;  // the RGB build's; 0 in the scalar one
};

FragmentTexels fragmentTexels() {
#ifdef STRATA_RGB_TRANSMITTANCE
    SurfaceOptics o = surfaceOptics();
    return FragmentTexels(vec4(o.premultiplied, 0.0), vec4(1.0 - o.transmittance, 0.0));
#else
    return FragmentTexels(surfaceColor(), vec4(0.0));
#endif
}

const FragmentTexels kNoFragment = FragmentTexels(vec4(0.0), vec4(0.0));
#endif
