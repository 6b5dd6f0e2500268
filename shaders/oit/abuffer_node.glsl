// A per-pixel linked-list node of the exact A-buffer: 24 bytes.
// Colour is kept as two half2 pairs, not rgba8, so quantisation stays far below 1/255.
struct FragmentNode {
    uint next;        // index + 1 of the next node; 0 ends the list
    float depth;      // window depth, reversed-Z: larger is nearer
    uint objectId;
    uint primitiveId;
    uint colorRG;     // packHalf2x16(r, g)
    uint colorBA;     // packHalf2x16(b, alpha)
};

layout(std430, binding = BIND_NODES) coherent buffer FragmentNodes {
    FragmentNode nodes[];
};
