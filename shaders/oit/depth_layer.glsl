// The layer test of core/render/depth_order.hpp on the GPU, shared by every exact resolve
// (ordered_composite.glsl) and the coplanarity detector (coplanarity_detect.comp.glsl), so
// "one depth layer" means the same thing wherever it is asked. The host sets both uniforms
// with setDepthOrderUniforms (core/oit/draw_transparent.hpp).
#ifndef STRATA_DEPTH_LAYER_GLSL
#define STRATA_DEPTH_LAYER_GLSL
uniform float uDepthOffset;   // n / (f - n) of the frame's camera
uniform float uTieTolerance;  // relative: Scene::depthTieUlps * 2^-23

// w = d + n / (f - n) for the reversed-Z window depth d: proportional to 1 / eye depth, so a
// relative difference in w is the same relative difference in eye depth. Larger is nearer.
float layerKey(float windowDepth) { return windowDepth + uDepthOffset; }

bool sameLayer(float a, float b) { return abs(a - b) <= uTieTolerance * max(a, b); }
#endif
