#version 450 core
// Test stage (tests/instanced_draw_gl_test.cpp): writes the object's id and its volume entry as
// the record delivered them to the fragment stage, and the material's alpha, which the draw sets
// as a uniform, so the test can tell each instance of a batched draw apart.
#include "surface.glsl"

layout(location = 0) out vec4 outProbe;

void main() {
    outProbe = vec4(float(uObjectId), float(uVolumeEntry), uAlpha, 1.0);
}
