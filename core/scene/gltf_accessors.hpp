#pragma once
// Reading glTF accessors: every element checked against its bufferView and buffer before it is
// read, normalized integers decoded as the specification says, sparse substitutions applied.
// Internal to the glTF loader (gltf_internal.hpp).
#include "scene/gltf_internal.hpp"

#include <glm/glm.hpp>
#include <tiny_gltf.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace strata::detail {

int componentSize(int componentType);  // 0 for a type glTF 2.0 accessors do not use
const char* typeName(int type);
int vectorComponents(int type);  // SCALAR 1 .. VEC4 4; matrices 0
// One component; normalized integers map to [0, 1] or [-1, 1].
double decode(const unsigned char* p, int componentType, bool normalized);

// A byte range inside a buffer, validated once: [data, data + size) is always readable.
struct Span {
    const unsigned char* data = nullptr;
    std::size_t size = 0;
};

// The bytes of bufferView `viewIndex`, checked against its buffer.
Span bufferViewSpan(const tinygltf::Model& model, int viewIndex, const std::string& what);

// Everything needed to read an accessor, checked against the buffers so that reading any
// element 0..count-1 stays in bounds.
struct AccessorView {
    std::size_t count = 0;
    int components = 0;
    int componentType = 0;
    bool normalized = false;
    Span dense;                 // empty data: all zeros (no bufferView)
    std::size_t offset = 0;     // accessor.byteOffset inside `dense`
    std::size_t stride = 0;
    // Sparse substitution (count 0 when the accessor is not sparse).
    std::size_t sparseCount = 0;
    Span sparseIndices, sparseValues;
    int sparseIndexType = 0;
};

// Checks accessor `index` as `wantComponents` components (and as indices when `indices`).
AccessorView checkAccessor(const tinygltf::Model& model, int index, int wantComponents, bool indices,
                           const std::string& what);

// Calls out(element, component, value) for every component: dense values (or zeros), then
// the sparse substitutions, so the last write for an element is the right one.
template <class Out>
void readAccessor(const AccessorView& v, const std::string& what, Out&& out) {
    int csize = componentSize(v.componentType);
    for (std::size_t e = 0; e < v.count; ++e) {
        const unsigned char* p = v.dense.data ? v.dense.data + v.offset + e * v.stride : nullptr;
        for (int c = 0; c < v.components; ++c)
            out(e, c, p ? decode(p + std::size_t(c) * std::size_t(csize), v.componentType, v.normalized) : 0.0);
    }
    std::size_t isize = std::size_t(componentSize(v.sparseIndexType));
    std::size_t elementSize = std::size_t(v.components) * std::size_t(csize);
    for (std::size_t s = 0; s < v.sparseCount; ++s) {
        auto target = std::size_t(decode(v.sparseIndices.data + s * isize, v.sparseIndexType, false));
        if (target >= v.count)
            fail(what + ": sparse index " + str(target) + " out of range (" + str(v.count) + " elements)");
        const unsigned char* p = v.sparseValues.data + s * elementSize;
        for (int c = 0; c < v.components; ++c)
            out(target, c, decode(p + std::size_t(c) * std::size_t(csize), v.componentType, v.normalized));
    }
}

std::vector<glm::vec3> readVec3(const tinygltf::Model& model, int accessor, const std::string& what,
                                const char* semantic);
std::vector<std::uint32_t> readIndices(const tinygltf::Model& model, int accessor, const std::string& what);

}  // namespace strata::detail
