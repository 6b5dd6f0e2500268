// What a resolve carries behind the fragments it has composited: one transmittance, or with
// STRATA_RGB_TRANSMITTANCE (a scene with a transmissive material, in the techniques that
// composite coloured filters exactly) one per channel. Written so that the same arithmetic,
// "color += transmittance * c; transmittance *= t", serves both.
#ifndef STRATA_TRANSMITTANCE_GLSL
#define STRATA_TRANSMITTANCE_GLSL
#ifdef STRATA_RGB_TRANSMITTANCE
#define Transmittance vec3
#else
#define Transmittance float
#endif
#endif
