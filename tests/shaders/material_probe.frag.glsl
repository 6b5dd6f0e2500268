#version 450 core
// Test stage (tests/material_gl_test.cpp): writes what the per-object material path delivered,
// so the test can read it back. Every fragment of an object writes the same values, so the
// result does not depend on which fragment lands last.
#include "surface.glsl"

layout(location = 0) out vec4 outTau;
layout(location = 1) out vec4 outAlbedo;
layout(location = 2) out vec4 outTransmittance;

void main() {
    outTau = vec4(uTau, 1.0);
    outAlbedo = vec4(uAlbedo, 1.0);
    outTransmittance = vec4(volumeTransmittance(0.5), 1.0);
}
