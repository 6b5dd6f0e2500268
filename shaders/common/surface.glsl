// Per-object material uniforms and the shaded colour of the current fragment.
#include "bindings.h"
#include "shading.glsl"
#include "shade_material.glsl"

// uObjectId is the object's (common/object_record.glsl, which common/material.glsl includes).
// The volumetric model (Barta & Kovacs; Material::tau and albedo): attenuation per metre for
// each channel and the single-scattering albedo, both zero for a thin surface.
uniform vec3 uTau;
uniform vec3 uAlbedo;

in vec3 vWorldNormal;
in vec3 vWorldPosition;

// The interpolated mesh normal, or for a stand-in the impostor texel's (common/scene_main.glsl).
vec3 surfaceNormal() {
    return kStandIn ? strataImpostorNormal : vWorldNormal;
}

// The fragment's effect on what lies behind it (common/shading_model.h's SurfaceOptics): its
// premultiplied colour and its transmittance per channel, coloured for a transmissive material.
// The techniques that composite RGB transmittance store this (oit/fragment_color.glsl).
SurfaceOptics surfaceOptics() {
    vec4 base = materialBaseColor();
#if defined(STRATA_TRANSMISSION) && !defined(STRATA_UNLIT)
    // BLEND glass covers by its alpha; OPAQUE glass covers its whole surface.
    return shadeTransmissive(base.rgb, uAlphaBlend ? base.a : 1.0, surfaceNormal(), vWorldPosition);
#else
    return surfaceOpticsOf(shadeMaterial(base.rgb, surfaceNormal(), vWorldPosition), base.a, vec3(0.0));
#endif
}

// The shaded colour and the alpha of the fragment (common/material.glsl); for a transmissive
// material the scalar form of its optics (shading_model.h's scalarOpacityForm). A material in the
// transmission build for its ior alone (transmission 0) filters nothing: its usual pair.
vec4 surfaceColor() {
#ifdef STRATA_TRANSMISSION
    if (uTransmission > 0.0) return scalarOpacityForm(surfaceOptics());
#endif
    vec4 base = materialBaseColor();
    return vec4(shadeMaterial(base.rgb, surfaceNormal(), vWorldPosition), base.a);
}

// What `distance` metres of this object's medium let through, per channel: exp(-tau d). Finite,
// and 1 at d = 0, because the loaders keep tau finite (kMaxTau in core/scene/scene.hpp): an
// infinite tau would give inf * 0 = NaN for a zero-length segment.
vec3 volumeTransmittance(float distance) {
    return exp(-uTau * distance);
}
