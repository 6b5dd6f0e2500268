#version 450 core
// LOD cost calibration (lod/lod_cost_calibration.cpp), the impostor side: slice quads given in
// clip space (each fills the viewport at its own depth), with the impostor vertex layout of
// core/render/stand_in.hpp: attribute 2 = (u, v, atlas layer, slice).
layout(location = 0) in vec3 inPosition;
layout(location = 2) in vec4 inSlice;

out vec4 vSlice;

void main() {
    vSlice = inSlice;
    gl_Position = vec4(inPosition, 1.0);
}
