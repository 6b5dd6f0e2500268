// A list resolve's node reads (abuffer_list.glsl, volume/volume_list.glsl). With NODE_TEXELS
// they go through an RGB32UI buffer texture over the pool, two texels a node (next, depth,
// objectId | primitiveId, colorRG, colorBA; oit/abuffer_node.h): llvmpipe loads a storage buffer
// lane by lane, and abuffer's resolve at 16 layers took 34 ms that way against 26 this way.
// Without it (ll's resolves where the pool is larger than a buffer texture can view), the
// storage buffer itself.
#ifndef STRATA_NODE_FETCH_GLSL
#define STRATA_NODE_FETCH_GLSL
#include "oit/abuffer_storage.glsl"

#ifdef NODE_TEXELS
layout(binding = BIND_NODE_TEXELS) uniform usamplerBuffer uNodeTexels;
uvec3 nodeFront(uint i) { return texelFetch(uNodeTexels, int(2u * i)).xyz; }
uvec3 nodeBack(uint i) { return texelFetch(uNodeTexels, int(2u * i + 1u)).xyz; }
uint nodeNext(uint i) { return nodeFront(i).x; }
float nodeDepth(uint i) { return uintBitsToFloat(nodeFront(i).y); }
uint nodeObject(uint i) { return nodeFront(i).z; }
uint nodePrimitive(uint i) { return nodeBack(i).x; }
uvec2 nodeColor(uint i) { return nodeBack(i).yz; }
#else
uint nodeNext(uint i) { return nodes[i].next; }
float nodeDepth(uint i) { return nodes[i].depth; }
uint nodeObject(uint i) { return nodes[i].objectId; }
uint nodePrimitive(uint i) { return nodes[i].primitiveId; }
uvec2 nodeColor(uint i) { return uvec2(nodes[i].colorRG, nodes[i].colorBA); }
#endif
#endif
