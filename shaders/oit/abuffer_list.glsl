// The A-buffer's per-pixel linked lists as ordered_composite.glsl reads them: node accessors
// and the iteration macro. Shared by the fragment and compute resolves (abuffer_resolve.*).
#include "abuffer_storage.glsl"
#include "oit/node_fetch.glsl"
#include "packed_color.glsl"

uint gFirstNode;  // the pixel's list head as a node index, 0xFFFFFFFF for an empty list

float fragmentDepth(uint i) { return nodeDepth(i); }
uint fragmentObject(uint i) { return nodeObject(i); }
uint fragmentPrimitive(uint i) { return nodePrimitive(i); }

void compositeFragment(uint i, inout vec3 color, inout Transmittance transmittance) {
    const uvec2 packedColor = nodeColor(i);
    compositePacked(packedColor.x, packedColor.y, color, transmittance);
}

void compositeFragmentInFront(uint i, inout vec3 color, inout Transmittance transmittance) {
    const uvec2 packedColor = nodeColor(i);
    compositePackedInFront(packedColor.x, packedColor.y, color, transmittance);
}
#define LIST_WALK_IN_ORDER  // ordered_composite.glsl: a list already in depth order composites as walked

// Links hold index + 1 with 0 ending the list, so "link - 1" ends at 0xFFFFFFFF.
#define FOR_EACH_FRAGMENT(i) for (uint i = gFirstNode; i != 0xFFFFFFFFu; i = nodeNext(i) - 1u)
#include "ordered_composite.glsl"

// The pixel's transparent fragments in depth order over `opaque`.
vec3 resolvePixel(ivec2 pixel, vec3 opaque) {
    gFirstNode = imageLoad(uHeads, pixel).r - 1u;
    vec3 color = vec3(0.0);
    Transmittance transmittance = Transmittance(1.0);
    compositeInDepthOrder(color, transmittance);
#ifdef LIST_TAIL
    compositeTail(pixel, color, transmittance);
#endif
    return color + transmittance * opaque;
}
