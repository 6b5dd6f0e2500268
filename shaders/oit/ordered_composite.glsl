// Composites one pixel's stored fragments front to back in the exact order of
// core/render/depth_order.hpp, the tie rule every exact path shares with the CPU ray cast:
//  1. a total order by (w, object, primitive), nearest first, where w = d + n / (f - n) for
//     the reversed-Z window depth d (w is proportional to 1 / eye depth, so a relative
//     difference in w is the same relative difference in eye depth);
//  2. consecutive fragments whose w differ by at most uTieTolerance * max(w) are one layer;
//  3. a layer composites in (object, primitive) order.
// All three steps depend only on the set of fragments, never on the order they arrived in.
//
// The including resolve defines, before including this file:
//   float fragmentDepth(uint i); uint fragmentObject(uint i); uint fragmentPrimitive(uint i);
//   void compositeFragment(uint i, inout vec3 color, inout Transmittance transmittance);
//   FOR_EACH_FRAGMENT(i): a loop header visiting every fragment index i of the pixel.
// Up to LOCAL_CAPACITY fragments sort in registers; longer lists are walked by repeated
// selection, O(n^2) but exact for any depth complexity.

#ifndef LOCAL_CAPACITY
#define LOCAL_CAPACITY 64
#endif
#define NO_FRAGMENT 0xFFFFFFFFu

#include "oit/depth_layer.glsl"
#include "oit/transmittance.glsl"

float orderKey(uint i) { return layerKey(fragmentDepth(i)); }

// Scene order inside a layer: object, then primitive, then nearer first.
bool sceneBefore(uint a, uint b) {
    uint oa = fragmentObject(a), ob = fragmentObject(b);
    if (oa != ob) return oa < ob;
    uint pa = fragmentPrimitive(a), pb = fragmentPrimitive(b);
    if (pa != pb) return pa < pb;
    return orderKey(a) > orderKey(b);
}

// The total order of step 1 (larger w is nearer).
bool depthBefore(uint a, uint b) {
    float ka = orderKey(a), kb = orderKey(b);
    if (ka != kb) return ka > kb;
    return sceneBefore(a, b);
}

// The fragment that follows `previous` in the total order (the first one for NO_FRAGMENT).
uint nextInDepthOrder(uint previous) {
    uint best = NO_FRAGMENT;
    FOR_EACH_FRAGMENT(i) {
        if (previous != NO_FRAGMENT && !depthBefore(previous, i)) continue;
        if (best == NO_FRAGMENT || depthBefore(i, best)) best = i;
    }
    return best;
}

void compositeLongList(inout vec3 color, inout Transmittance transmittance) {
    uint previous = NO_FRAGMENT;  // the last fragment of the layer composited last
    while (true) {
        uint first = nextInDepthOrder(previous);
        if (first == NO_FRAGMENT) break;
        uint last = first;
        while (true) {
            uint next = nextInDepthOrder(last);
            if (next == NO_FRAGMENT || !sameLayer(orderKey(last), orderKey(next))) break;
            last = next;
        }
        // The layer is the range [first, last] of the total order; walk it in scene order.
        uint done = NO_FRAGMENT;
        while (true) {
            uint best = NO_FRAGMENT;
            FOR_EACH_FRAGMENT(i) {
                bool inLayer = i == first || i == last || (depthBefore(first, i) && depthBefore(i, last));
                if (!inLayer) continue;
                if (done != NO_FRAGMENT && !sceneBefore(done, i)) continue;
                if (best == NO_FRAGMENT || sceneBefore(i, best)) best = i;
            }
            if (best == NO_FRAGMENT) break;
            compositeFragment(best, color, transmittance);
            done = best;
        }
        previous = last;
    }
}

#ifdef LIST_WALK_IN_ORDER
// Where the fragments already run one way in depth as FOR_EACH_FRAGMENT visits them, each a layer
// of its own (no two consecutive ones within the tie tolerance), the total order is the walk's or
// its reverse and every layer holds one fragment: they composite as they are walked, nearest
// first with compositeFragment or farthest first with compositeFragmentInFront (which the
// includer defines), and nothing is held in arrays or sorted. A list stored in the order its
// objects were drawn runs so wherever they were drawn by depth (Strata draws nearest first).
// Returns false, having composited nothing, where the fragments do not run one way.
bool compositeIfWalkInOrder(inout vec3 color, inout Transmittance transmittance) {
    float previous = 0.0;
    int direction = 0;  // 1: each fragment farther than the last (nearest first); -1: nearer
    bool first = true;
    FOR_EACH_FRAGMENT(i) {
        const float key = orderKey(i);
        if (!first) {
            if (sameLayer(previous, key)) return false;
            const int step = key < previous ? 1 : -1;
            if (direction == 0) direction = step;
            else if (step != direction) return false;
        }
        previous = key;
        first = false;
    }
    if (direction >= 0) {
        FOR_EACH_FRAGMENT(i) compositeFragment(i, color, transmittance);
    } else {
        // In front of each other, and all of them behind what the caller already holds.
        vec3 listColor = vec3(0.0);
        Transmittance listTransmittance = Transmittance(1.0);
        FOR_EACH_FRAGMENT(i) compositeFragmentInFront(i, listColor, listTransmittance);
        color += transmittance * listColor;
        transmittance *= listTransmittance;
    }
    return true;
}
#endif

void compositeInDepthOrder(inout vec3 color, inout Transmittance transmittance) {
#ifdef LIST_WALK_IN_ORDER
    if (compositeIfWalkInOrder(color, transmittance)) return;
#endif
    // Keys stay in registers beside the indices: the sort reads memory only on an exact key
    // tie, and the layer pass only inside a layer of two or more (coincident surfaces).
    uint local[LOCAL_CAPACITY];
    float localKey[LOCAL_CAPACITY];
    uint count = 0u;
    bool tooLong = false;
    FOR_EACH_FRAGMENT(i) {
        if (count == LOCAL_CAPACITY) { tooLong = true; break; }
        local[count] = i;
        localKey[count] = orderKey(i);
        count++;
    }
    if (tooLong) {
        compositeLongList(color, transmittance);
        return;
    }
    // Lists come out in (reverse) arrival order, which in most scenes runs mostly one way in
    // depth: objects drawn near to far, or far to near. Insertion sort in the direction the
    // list already runs costs O(n) on such a list where the other direction costs O(n^2)
    // (a third of the resolve on 16 layers); a list sorted farthest first is then reversed.
    bool farFirst = count > 1u && localKey[0] < localKey[count - 1u];
    for (uint a = 1u; a < count; ++a) {
        uint f = local[a];
        float key = localKey[a];
        uint j = a;
        // Written as "if (!...) break" on purpose: llvmpipe (Mesa 22.3) miscompiled the
        // equivalent "while (j > 0u && ...)" and produced wrongly ordered lists.
        while (j > 0u) {
            float k = localKey[j - 1u];
            bool first = (key != k ? key > k : sceneBefore(f, local[j - 1u])) != farFirst;
            if (!first) break;
            local[j] = local[j - 1u];
            localKey[j] = k;
            j--;
        }
        local[j] = f;
        localKey[j] = key;
    }
    if (farFirst) {
        for (uint a = 0u, b = count - 1u; a < b; ++a, --b) {
            uint t = local[a];
            local[a] = local[b];
            local[b] = t;
            float tk = localKey[a];
            localKey[a] = localKey[b];
            localKey[b] = tk;
        }
    }
    uint start = 0u;
    for (uint end = 1u; end <= count; ++end) {
        if (end < count && sameLayer(localKey[end - 1u], localKey[end])) continue;
        // local[start, end) is one layer: insertion sort it into scene order, then composite.
        for (uint a = start + 1u; a < end; ++a) {
            uint f = local[a];
            uint j = a;
            while (j > start) {
                if (!sceneBefore(f, local[j - 1u])) break;
                local[j] = local[j - 1u];
                j--;
            }
            local[j] = f;
        }
        for (uint a = start; a < end; ++a) compositeFragment(local[a], color, transmittance);
        start = end;
    }
}
