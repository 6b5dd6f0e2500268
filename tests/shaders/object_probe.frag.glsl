#version 450 core
// Test stage (tests/instanced_draw_gl_test.cpp): writes the object's id and its volume entry as
// the record delivered them to the fragment stage, the material's alpha, which the draw sets as
// a uniform, and the primitive id, which every instance must count from 0 (the stores key
// fragments by object and primitive).
#include "surface.glsl"

layout(location = 0) out vec4 outProbe;

void main() {
    outProbe = vec4(float(uObjectId), float(uVolumeEntry), uAlpha, float(gl_PrimitiveID));
}
