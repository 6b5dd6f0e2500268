// Put after #version in the fragment stage of every scene program (render/scene_program.cpp):
// the stage's own main() is renamed, and common/scene_main.glsl, appended at the end, calls it
// after the layered-impostor alpha test. So every technique's passes take a stand-in's
// fragments exactly as they take a mesh's, with no code of their own.
#define main strataSceneFragmentMain

// Set while a stand-in draws (render/stand_in.hpp); the wrapper then sets the normal below.
uniform bool uImpostor;
// The impostor texel's normal, in world space: what surfaceNormal() returns for a stand-in.
vec3 strataImpostorNormal;
