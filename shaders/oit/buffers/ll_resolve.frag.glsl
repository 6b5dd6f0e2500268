#version 450 core
// Linked-list resolve: like the A-buffer's (sort by (depth, object id, primitive id), composite
// over the opaque colour), plus the tail layer behind the stored fragments.
#include "bindings.glsl"
#include "oit/abuffer_node.glsl"
#include "buffer_bindings.glsl"
#include "tail_resolve.glsl"

#ifndef LOCAL_CAPACITY
#define LOCAL_CAPACITY 64
#endif

layout(binding = BIND_HEADS, r32ui) uniform coherent uimage2D uHeads;
layout(binding = BIND_OPAQUE_COLOR) uniform sampler2D uOpaqueColor;
layout(location = 0) out vec4 outColor;

bool before(uint a, uint b) {
    FragmentNode na = nodes[a];
    FragmentNode nb = nodes[b];
    if (na.depth != nb.depth) return na.depth > nb.depth;
    if (na.objectId != nb.objectId) return na.objectId < nb.objectId;
    return na.primitiveId < nb.primitiveId;
}

void composite(uint n, inout vec3 color, inout float transmittance) {
    vec2 rg = unpackHalf2x16(nodes[n].colorRG);
    vec2 ba = unpackHalf2x16(nodes[n].colorBA);
    color += transmittance * ba.y * vec3(rg, ba.x);
    transmittance *= 1.0 - ba.y;
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec3 opaque = texelFetch(uOpaqueColor, pixel, 0).rgb;
    uint head = imageLoad(uHeads, pixel).r;
    vec3 color = vec3(0.0);
    float transmittance = 1.0;

    uint local[LOCAL_CAPACITY];
    uint count = 0u;
    bool tooLong = false;
    for (uint n = head; n != 0u; n = nodes[n - 1u].next) {
        if (count == LOCAL_CAPACITY) { tooLong = true; break; }
        uint node = n - 1u;
        uint j = count;
        while (j > 0u) {  // see resolve_array.frag.glsl: no `&&` with local[j - 1] here
            if (!before(node, local[j - 1u])) break;
            local[j] = local[j - 1u];
            j--;
        }
        local[j] = node;
        count++;
    }
    if (!tooLong) {
        for (uint i = 0u; i < count; ++i) composite(local[i], color, transmittance);
    } else {
        uint previous = 0xFFFFFFFFu;
        while (true) {
            uint best = 0xFFFFFFFFu;
            for (uint n = head; n != 0u; n = nodes[n - 1u].next) {
                uint node = n - 1u;
                if (previous != 0xFFFFFFFFu && !before(previous, node)) continue;
                if (best == 0xFFFFFFFFu || before(node, best)) best = node;
            }
            if (best == 0xFFFFFFFFu) break;
            composite(best, color, transmittance);
            previous = best;
        }
    }
    compositeTail(pixel, color, transmittance);
    outColor = vec4(color + transmittance * opaque, 1.0);
}
