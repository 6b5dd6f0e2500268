#version 450 core
// A-buffer resolve: composites each pixel's linked list over the opaque colour in the exact
// order of ordered_composite.glsl (depth, near-equal depths in object order). `ll` uses this
// resolve too, with LIST_TAIL defined: its overflowed fragments, blended into a tail layer,
// composite behind the sorted ones.
#include "bindings.glsl"
#include "abuffer_node.glsl"
#ifdef LIST_TAIL
#include "buffers/buffer_bindings.glsl"
#include "buffers/tail_resolve.glsl"
#endif

layout(binding = BIND_HEADS, r32ui) uniform coherent uimage2D uHeads;
layout(binding = BIND_OPAQUE_COLOR) uniform sampler2D uOpaqueColor;

layout(location = 0) out vec4 outColor;

uint gFirstNode;  // the pixel's list head as a node index, 0xFFFFFFFF for an empty list

float fragmentDepth(uint i) { return nodes[i].depth; }
uint fragmentObject(uint i) { return nodes[i].objectId; }
uint fragmentPrimitive(uint i) { return nodes[i].primitiveId; }

void compositeFragment(uint i, inout vec3 color, inout float transmittance) {
    vec2 rg = unpackHalf2x16(nodes[i].colorRG);
    vec2 ba = unpackHalf2x16(nodes[i].colorBA);
    color += transmittance * ba.y * vec3(rg, ba.x);
    transmittance *= 1.0 - ba.y;
}

// Links hold index + 1 with 0 ending the list, so "link - 1" ends at 0xFFFFFFFF.
#define FOR_EACH_FRAGMENT(i) for (uint i = gFirstNode; i != 0xFFFFFFFFu; i = nodes[i].next - 1u)
#include "ordered_composite.glsl"

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec3 opaque = texelFetch(uOpaqueColor, pixel, 0).rgb;
    gFirstNode = imageLoad(uHeads, pixel).r - 1u;
    vec3 color = vec3(0.0);
    float transmittance = 1.0;
    compositeInDepthOrder(color, transmittance);
#ifdef LIST_TAIL
    compositeTail(pixel, color, transmittance);
#endif
    outColor = vec4(color + transmittance * opaque, 1.0);
}
