// One stored fragment of the array-based buffers (fab, kbuffer, sbuffer): 20 bytes, std430
// stride 20. Colour as two half2 pairs like the A-buffer's nodes, so quantisation stays far
// below 1/255 and the buffers can equal the reference.
#include "buffer_bindings.glsl"

struct FragmentEntry {
    float depth;       // window depth, reversed-Z: larger is nearer
    uint objectId;
    uint primitiveId;
    uint colorRG;      // packHalf2x16(r, g)
    uint colorBA;      // packHalf2x16(b, alpha)
};

layout(std430, binding = BIND_ENTRIES) coherent buffer FragmentEntries {
    FragmentEntry entries[];
};

FragmentEntry makeEntry(float depth, uint objectId, uint primitiveId, vec4 color) {
    return FragmentEntry(depth, objectId, primitiveId, packHalf2x16(color.rg), packHalf2x16(color.ba));
}
