#version 450 core
// f2b-3p, full screen: the far edge of the current layer's tie band (layer_tie.glsl) as depth,
// so that the counting and shading passes test GL_GEQUAL against it in hardware and shade only
// the layer's fragments (and the few behind it within the edge's rounding margin), not every
// fragment left behind the layer. The shaders still decide exactly (coplanar_layer.glsl); the
// hardware test only lets a superset through. No layer here: 1 (the near plane), which lets
// nothing further through that the shaders would keep.
#include "bindings.h"
#include "coplanar_layer.glsl"
#include "layer_tie.glsl"

layout(binding = BIND_COPLANAR_STATE) uniform sampler2D uState;

void main() {
    float anchor = texelFetch(uState, ivec2(gl_FragCoord.xy), 0).r;
    gl_FragDepth = hasAnchor(anchor) ? layerFarEdge(anchor) : 1.0;
}
