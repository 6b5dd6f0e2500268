#version 450 core
// LOD cost calibration (lod/lod_cost_calibration.cpp), the geometry side: a dense mesh drawn
// with the scene's own vertex stage (common/scene.vert.glsl) and a plain diffuse term, so the
// time is the vertex work a scene draw pays plus a light fragment cost.
in vec3 vWorldNormal;
layout(location = 0) out vec4 outColor;

void main() {
    const vec3 light = normalize(vec3(0.35, 0.8, 0.5));
    outColor = vec4(vec3(0.1 + 0.8 * max(dot(normalize(vWorldNormal), light), 0.0)), 1.0);
}
