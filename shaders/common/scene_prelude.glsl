// Put after #version and the defines in the fragment stage of every scene program
// (render/scene_program.cpp). A scene program is built twice: as is, and, the first time a
// stand-in draws with it, with STRATA_IMPOSTOR defined (render/stand_in.hpp). In that variant
// the stage's own main() is renamed and common/scene_main.glsl, appended at the end, calls it
// after the layered-impostor alpha test; so every technique's passes take a stand-in's fragments
// exactly as they take a mesh's, with no code of their own. The geometry build has none of it:
// on llvmpipe even an untaken uniform branch around the texture fetch doubled a pass's time.
#ifdef STRATA_IMPOSTOR
#define main strataSceneFragmentMain
const bool kStandIn = true;
#else
const bool kStandIn = false;
#endif

// The impostor texel's normal, in world space: what surfaceNormal() returns for a stand-in.
vec3 strataImpostorNormal;
