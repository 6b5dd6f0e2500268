#version 450 core
// A-buffer resolve: sorts each pixel's list front to back by (depth, object id, primitive id)
// and composites it over the opaque colour. Short lists are insertion-sorted in registers;
// a list longer than LOCAL_CAPACITY is walked by repeated selection of the next key, O(n^2)
// but exact for any depth complexity. `ll` uses this resolve too, with LIST_TAIL defined: its
// overflowed fragments, blended into a tail layer, composite behind the sorted ones.
#include "bindings.glsl"
#include "abuffer_node.glsl"
#ifdef LIST_TAIL
#include "buffers/buffer_bindings.glsl"
#include "buffers/tail_resolve.glsl"
#endif

#ifndef LOCAL_CAPACITY
#define LOCAL_CAPACITY 64
#endif

layout(binding = BIND_HEADS, r32ui) uniform coherent uimage2D uHeads;
layout(binding = BIND_OPAQUE_COLOR) uniform sampler2D uOpaqueColor;

layout(location = 0) out vec4 outColor;

// True when node a must be composited before node b.
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

    // Depths stay in registers beside the node indices: a comparison reads memory only on a
    // depth tie (coplanar surfaces), where object and primitive ids decide.
    uint local[LOCAL_CAPACITY];
    float localDepth[LOCAL_CAPACITY];
    uint count = 0u;
    bool tooLong = false;
    for (uint n = head; n != 0u; n = nodes[n - 1u].next) {
        if (count == LOCAL_CAPACITY) { tooLong = true; break; }
        uint node = n - 1u;
        float depth = nodes[node].depth;
        uint j = count;
        // Written as "if (!...) break" on purpose: llvmpipe (Mesa 22.3) miscompiled the
        // equivalent "while (j > 0u && before(...))" and produced wrongly ordered lists.
        while (j > 0u) {
            float d = localDepth[j - 1u];
            bool first = depth != d ? depth > d : before(node, local[j - 1u]);
            if (!first) break;
            local[j] = local[j - 1u];
            localDepth[j] = d;
            j--;
        }
        local[j] = node;
        localDepth[j] = depth;
        count++;
    }

    if (!tooLong) {
        for (uint i = 0u; i < count; ++i) composite(local[i], color, transmittance);
    } else {
        // Selection walk: each step finds the first node after the previous one in key order.
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
#ifdef LIST_TAIL
    compositeTail(pixel, color, transmittance);
#endif
    outColor = vec4(color + transmittance * opaque, 1.0);
}
