#include "scene/gltf_accessors.hpp"

#include <cstring>

namespace strata::detail {
namespace {

// An accessor without a bufferView is all zeros (plus sparse values); its count is not bounded
// by any buffer, so cap it to keep a hostile file from asking for a huge allocation.
constexpr std::size_t kMaxCountWithoutView = std::size_t(1) << 24;

}  // namespace

Span bufferViewSpan(const tinygltf::Model& model, int viewIndex, const std::string& what) {
    if (viewIndex < 0 || std::size_t(viewIndex) >= model.bufferViews.size())
        fail(what + ": bufferView " + str(viewIndex) + " does not exist");
    const tinygltf::BufferView& view = model.bufferViews[std::size_t(viewIndex)];
    if (view.buffer < 0 || std::size_t(view.buffer) >= model.buffers.size())
        fail(what + ": bufferView " + str(viewIndex) + " refers to buffer " + str(view.buffer) +
             ", which does not exist");
    const auto& bytes = model.buffers[std::size_t(view.buffer)].data;
    // Written as two comparisons so that offset + length cannot overflow.
    if (view.byteOffset > bytes.size() || view.byteLength > bytes.size() - view.byteOffset)
        fail(what + ": bufferView " + str(viewIndex) + " (offset " + str(view.byteOffset) +
             ", length " + str(view.byteLength) + ") exceeds buffer " + str(view.buffer) + " (" +
             str(bytes.size()) + " bytes)");
    return {bytes.data() + view.byteOffset, view.byteLength};
}

int componentSize(int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
        default: return 0;  // INT and DOUBLE are not glTF 2.0 accessor component types
    }
}

const char* typeName(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR: return "SCALAR";
        case TINYGLTF_TYPE_VEC2: return "VEC2";
        case TINYGLTF_TYPE_VEC3: return "VEC3";
        case TINYGLTF_TYPE_VEC4: return "VEC4";
        case TINYGLTF_TYPE_MAT2: return "MAT2";
        case TINYGLTF_TYPE_MAT3: return "MAT3";
        case TINYGLTF_TYPE_MAT4: return "MAT4";
        default: return "unknown";
    }
}

// Component count for the vector types the loader reads; matrices are never geometry (and
// their column padding rules for small types are not worth supporting), so they count as 0.
int vectorComponents(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR: return 1;
        case TINYGLTF_TYPE_VEC2: return 2;
        case TINYGLTF_TYPE_VEC3: return 3;
        case TINYGLTF_TYPE_VEC4: return 4;
        default: return 0;
    }
}

// Decodes one component; normalized integers follow the spec's max(c / MAX, -1) mapping.
double decode(const unsigned char* p, int componentType, bool normalized) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
            std::int8_t v; std::memcpy(&v, p, 1);
            return normalized ? std::max(v / 127.0, -1.0) : double(v);
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
            std::uint8_t v; std::memcpy(&v, p, 1);
            return normalized ? v / 255.0 : double(v);
        }
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            std::int16_t v; std::memcpy(&v, p, 2);
            return normalized ? std::max(v / 32767.0, -1.0) : double(v);
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            std::uint16_t v; std::memcpy(&v, p, 2);
            return normalized ? v / 65535.0 : double(v);
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
            std::uint32_t v; std::memcpy(&v, p, 4);
            return normalized ? v / 4294967295.0 : double(v);
        }
        default: {  // FLOAT (checked by the caller)
            float v; std::memcpy(&v, p, 4);
            return double(v);
        }
    }
}

bool isIndexType(int componentType) {
    return componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
           componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
           componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
}

AccessorView checkAccessor(const tinygltf::Model& model, int index, int wantComponents,
                           bool indices, const std::string& what) {
    if (index < 0 || std::size_t(index) >= model.accessors.size())
        fail(what + ": accessor " + str(index) + " does not exist");
    const tinygltf::Accessor& acc = model.accessors[std::size_t(index)];
    std::string where = what + " (accessor " + str(index) + ")";
    AccessorView v;
    v.components = vectorComponents(acc.type);
    if (v.components != wantComponents)
        fail(where + ": type " + typeName(acc.type) + ", expected " +
             (wantComponents == 1 ? "SCALAR" : "VEC" + str(wantComponents)));
    v.componentType = acc.componentType;
    int csize = componentSize(acc.componentType);
    if (csize == 0) fail(where + ": component type " + str(acc.componentType) + " is not allowed");
    if (indices && !isIndexType(acc.componentType))
        fail(where + ": indices must be UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT, not component type " +
             str(acc.componentType));
    v.normalized = acc.normalized && !indices && acc.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT;
    v.count = acc.count;
    std::size_t elementSize = std::size_t(v.components) * std::size_t(csize);

    if (acc.bufferView < 0) {
        if (v.count > kMaxCountWithoutView)
            fail(where + ": count " + str(v.count) + " without a bufferView is too large");
    } else {
        v.dense = bufferViewSpan(model, acc.bufferView, where);
        const tinygltf::BufferView& view = model.bufferViews[std::size_t(acc.bufferView)];
        v.stride = view.byteStride ? view.byteStride : elementSize;
        if (v.stride < elementSize)
            fail(where + ": byteStride " + str(v.stride) + " is smaller than the element (" +
                 str(elementSize) + " bytes)");
        v.offset = acc.byteOffset;
        if (v.count > 0) {
            // Last element must end inside the view: offset + stride*(count-1) + size <= length.
            bool fits = v.offset <= v.dense.size && elementSize <= v.dense.size - v.offset &&
                        (v.count - 1) <= (v.dense.size - v.offset - elementSize) / v.stride;
            if (!fits)
                fail(where + ": " + str(v.count) + " elements at offset " + str(v.offset) + " stride " +
                     str(v.stride) + " exceed bufferView " + str(acc.bufferView) + " (" +
                     str(v.dense.size) + " bytes)");
        }
    }

    if (acc.sparse.isSparse) {
        const auto& sp = acc.sparse;
        if (sp.count < 1 || std::size_t(sp.count) > v.count)
            fail(where + ": sparse count " + str(sp.count) + " outside 1.." + str(v.count));
        if (!isIndexType(sp.indices.componentType))
            fail(where + ": sparse indices component type " + str(sp.indices.componentType) + " is not allowed");
        if (sp.indices.byteOffset < 0 || sp.values.byteOffset < 0)
            fail(where + ": negative sparse byteOffset");
        v.sparseCount = std::size_t(sp.count);
        v.sparseIndexType = sp.indices.componentType;
        auto sub = [&](int viewIndex, int byteOffset, std::size_t bytesEach, const char* part) {
            Span s = bufferViewSpan(model, viewIndex, where + " sparse " + part);
            std::size_t off = std::size_t(byteOffset);
            if (off > s.size || (s.size - off) / bytesEach < v.sparseCount)
                fail(where + ": sparse " + part + " exceed bufferView " + str(viewIndex));
            return Span{s.data + off, s.size - off};
        };
        v.sparseIndices = sub(sp.indices.bufferView, sp.indices.byteOffset,
                              std::size_t(componentSize(sp.indices.componentType)), "indices");
        v.sparseValues = sub(sp.values.bufferView, sp.values.byteOffset, elementSize, "values");
    }
    return v;
}

std::vector<glm::vec3> readVec3(const tinygltf::Model& model, int accessor, const std::string& what,
                                const char* semantic) {
    AccessorView v = checkAccessor(model, accessor, 3, false, what + " " + semantic);
    std::vector<glm::vec3> out(v.count);
    readAccessor(v, what + " " + semantic, [&](std::size_t e, int c, double x) { out[e][c] = float(x); });
    for (const auto& p : out)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            fail(what + ": non-finite " + semantic + " value");
    return out;
}

std::vector<std::uint32_t> readIndices(const tinygltf::Model& model, int accessor, const std::string& what) {
    AccessorView v = checkAccessor(model, accessor, 1, true, what + " indices");
    std::vector<std::uint32_t> out(v.count);
    readAccessor(v, what + " indices", [&](std::size_t e, int, double x) { out[e] = std::uint32_t(x); });
    return out;
}

}  // namespace strata::detail
