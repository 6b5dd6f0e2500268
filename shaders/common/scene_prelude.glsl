// Put after #version and the defines in the fragment stage of every scene program
// (render/scene_program.cpp). A scene program is built twice: as is, and, the first time a
// stand-in draws with it, with STRATA_IMPOSTOR defined (render/stand_in.hpp). In that variant
// the stage's own main() is renamed and common/scene_main.glsl, appended at the end, calls it
// after the layered-impostor alpha test; so every technique's passes take a stand-in's fragments
// exactly as they take a mesh's, with no code of their own. The geometry build has none of it:
// on llvmpipe even an untaken uniform branch around the texture fetch doubled a pass's time.
//
// A MASK material's build (STRATA_ALPHA_MASK, render/scene_program.hpp's variants) is wrapped
// the same way: the wrapper discards a fragment whose alpha is below the cutoff before the
// stage's main() runs, so every pass that draws the object, opaque or transparent, depth-only
// or counting, sees the cut-out and none needs code of its own.
#if defined(STRATA_IMPOSTOR) || defined(STRATA_ALPHA_MASK)
#define STRATA_WRAPPED_MAIN
#define main strataSceneFragmentMain
#endif
#ifdef STRATA_IMPOSTOR
const bool kStandIn = true;
#else
const bool kStandIn = false;
#endif

// Early fragment tests for a pass whose fragments have no side effects (no image store, no
// atomic): the test then only saves work. In a wrapped variant the wrapper discards, and
// under early tests an occlusion query counts samples before the shader runs (and depth is
// written), so the texels the alpha test rejects would be counted; those variants test late
// instead. Passes with side effects keep layout(early_fragment_tests): the wrapper discards
// before any of them.
#ifdef STRATA_WRAPPED_MAIN
#define STRATA_EARLY_TESTS_NO_SIDE_EFFECTS
#else
#define STRATA_EARLY_TESTS_NO_SIDE_EFFECTS layout(early_fragment_tests) in;
#endif

// The impostor texel's normal, in world space: what surfaceNormal() returns for a stand-in.
vec3 strataImpostorNormal;
// Its baked albedo (the base colour texture x COLOR_0 there), which common/material.glsl's
// materialBaseColor() takes in place of the texture for a stand-in; 1 where none was baked.
vec4 strataImpostorAlbedo = vec4(1.0);
