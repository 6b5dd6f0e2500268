#include "scene/gltf_schema.hpp"

#include "scene/gltf_ignored.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string_view>
#include <stdexcept>
#include <vector>

namespace strata::detail {
namespace {

using json = nlohmann::json;

struct Problem : std::runtime_error {
    using std::runtime_error::runtime_error;
};

[[noreturn]] void bad(const std::string& path, const char* expected) {
    throw Problem(path + ": expected " + expected);
}

// glTF's schema says "integer"; JSON writers sometimes emit 3.0, which is harmless.
bool isUint(const json& v) {
    if (v.is_number_unsigned()) return true;
    if (v.is_number_integer()) return v.get<std::int64_t>() >= 0;
    if (v.is_number_float()) {
        double d = v.get<double>();
        return d >= 0.0 && d <= 4294967295.0 && std::floor(d) == d;
    }
    return false;
}

const json* member(const json& obj, const char* key) {
    auto it = obj.find(key);
    return it == obj.end() ? nullptr : &*it;
}

std::string at(const std::string& path, const char* key) { return path.empty() ? key : path + "." + key; }
std::string at(const std::string& path, std::size_t i) { return path + "[" + std::to_string(i) + "]"; }

void object(const json& v, const std::string& path) { if (!v.is_object()) bad(path, "an object"); }

void uintKey(const json& o, const char* key, const std::string& path) {
    if (const json* v = member(o, key); v && !isUint(*v)) bad(at(path, key), "an unsigned integer");
}
void numberKey(const json& o, const char* key, const std::string& path) {
    if (const json* v = member(o, key); v && !v->is_number()) bad(at(path, key), "a number");
}
void boolKey(const json& o, const char* key, const std::string& path) {
    if (const json* v = member(o, key); v && !v->is_boolean()) bad(at(path, key), "a boolean");
}
void stringKey(const json& o, const char* key, const std::string& path) {
    if (const json* v = member(o, key); v && !v->is_string()) bad(at(path, key), "a string");
}
void numbersKey(const json& o, const char* key, const std::string& path) {
    const json* v = member(o, key);
    if (!v) return;
    if (!v->is_array()) bad(at(path, key), "an array of numbers");
    for (const json& x : *v)
        if (!x.is_number()) bad(at(path, key), "an array of numbers");
}
void uintsKey(const json& o, const char* key, const std::string& path) {
    const json* v = member(o, key);
    if (!v) return;
    if (!v->is_array()) bad(at(path, key), "an array of unsigned integers");
    for (const json& x : *v)
        if (!isUint(x)) bad(at(path, key), "an array of unsigned integers");
}

// Calls fn(element, path) for each element of the array `key` of `o`, which must hold objects.
template <class Fn>
void eachObject(const json& o, const char* key, const std::string& path, Fn&& fn) {
    const json* v = member(o, key);
    if (!v) return;
    if (!v->is_array()) bad(at(path, key), "an array");
    for (std::size_t i = 0; i < v->size(); ++i) {
        std::string p = at(at(path, key), i);
        object((*v)[i], p);
        fn((*v)[i], p);
    }
}

template <class Fn>
void objectKey(const json& o, const char* key, const std::string& path, Fn&& fn) {
    if (const json* v = member(o, key)) {
        object(*v, at(path, key));
        fn(*v, at(path, key));
    }
}

void textureInfo(const json& o, const char* key, const std::string& path) {
    objectKey(o, key, path, [](const json& t, const std::string& p) {
        uintKey(t, "index", p);
        uintKey(t, "texCoord", p);
        numberKey(t, "scale", p);
        numberKey(t, "strength", p);
    });
}

void checkDocument(const json& doc, IgnoredLog* ignored) {
    object(doc, "document");
    uintKey(doc, "scene", "");
    for (const char* key : {"extensionsUsed", "extensionsRequired"}) {
        if (const json* v = member(doc, key)) {
            if (!v->is_array()) bad(key, "an array of strings");
            for (const json& x : *v)
                if (!x.is_string()) bad(key, "an array of strings");
        }
    }
    // Refused here, before tinygltf reads buffers and images for a file that cannot be drawn.
    if (const json* required = member(doc, "extensionsRequired"))
        for (const json& x : *required)
            if (!implementedExtension(x.get<std::string>()))
                throw Problem(requiredExtensionProblem(x.get<std::string>()));
    eachObject(doc, "accessors", "", [](const json& a, const std::string& p) {
        for (const char* k : {"bufferView", "byteOffset", "componentType", "count"}) uintKey(a, k, p);
        boolKey(a, "normalized", p);
        stringKey(a, "type", p);
        numbersKey(a, "min", p);
        numbersKey(a, "max", p);
        objectKey(a, "sparse", p, [](const json& s, const std::string& sp) {
            uintKey(s, "count", sp);
            objectKey(s, "indices", sp, [](const json& i, const std::string& ip) {
                for (const char* k : {"bufferView", "byteOffset", "componentType"}) uintKey(i, k, ip);
            });
            objectKey(s, "values", sp, [](const json& v, const std::string& vp) {
                for (const char* k : {"bufferView", "byteOffset"}) uintKey(v, k, vp);
            });
        });
    });
    eachObject(doc, "bufferViews", "", [](const json& v, const std::string& p) {
        for (const char* k : {"buffer", "byteOffset", "byteLength", "byteStride", "target"}) uintKey(v, k, p);
    });
    eachObject(doc, "buffers", "", [](const json& b, const std::string& p) {
        uintKey(b, "byteLength", p);
        stringKey(b, "uri", p);
    });
    eachObject(doc, "materials", "", [](const json& m, const std::string& p) {
        objectKey(m, "pbrMetallicRoughness", p, [](const json& pbr, const std::string& pp) {
            numbersKey(pbr, "baseColorFactor", pp);
            numberKey(pbr, "metallicFactor", pp);
            numberKey(pbr, "roughnessFactor", pp);
            textureInfo(pbr, "baseColorTexture", pp);
            textureInfo(pbr, "metallicRoughnessTexture", pp);
        });
        for (const char* k : {"normalTexture", "occlusionTexture", "emissiveTexture"}) textureInfo(m, k, p);
        numbersKey(m, "emissiveFactor", p);
        stringKey(m, "alphaMode", p);
        numberKey(m, "alphaCutoff", p);
        boolKey(m, "doubleSided", p);
    });
    eachObject(doc, "meshes", "", [](const json& m, const std::string& p) {
        if (!member(m, "primitives")) bad(at(p, "primitives"), "an array (required)");
        eachObject(m, "primitives", p, [](const json& prim, const std::string& pp) {
            objectKey(prim, "attributes", pp, [](const json& attrs, const std::string& ap) {
                for (const auto& [name, index] : attrs.items())
                    if (!isUint(index)) bad(at(ap, name.c_str()), "an accessor index");
            });
            for (const char* k : {"indices", "material", "mode"}) uintKey(prim, k, pp);
            eachObject(prim, "targets", pp, [](const json&, const std::string&) {});
        });
        numbersKey(m, "weights", p);
    });
    std::size_t nodeIndex = 0;
    eachObject(doc, "nodes", "", [&](const json& n, const std::string& p) {
        uintsKey(n, "children", p);
        for (const char* k : {"camera", "skin", "mesh"}) uintKey(n, k, p);
        for (const char* k : {"matrix", "rotation", "scale", "translation", "weights"}) numbersKey(n, k, p);
        // glTF forbids both (validator: NODE_MATRIX_TRS); tinygltf keeps the matrix and drops the rest.
        if (ignored && member(n, "matrix") && (member(n, "translation") || member(n, "rotation") || member(n, "scale")))
            ignored->note("matrix and TRS", "node has both matrix and translation/rotation/scale: TRS ignored",
                          "node " + std::to_string(nodeIndex));
        ++nodeIndex;
    });
    eachObject(doc, "scenes", "", [](const json& s, const std::string& p) { uintsKey(s, "nodes", p); });
    eachObject(doc, "textures", "", [](const json& t, const std::string& p) {
        uintKey(t, "sampler", p);
        uintKey(t, "source", p);
    });
    eachObject(doc, "images", "", [](const json& i, const std::string& p) {
        stringKey(i, "uri", p);
        stringKey(i, "mimeType", p);
        uintKey(i, "bufferView", p);
    });
    for (const char* key : {"animations", "cameras", "samplers", "skins"})
        eachObject(doc, key, "", [](const json&, const std::string&) {});
}

// Everywhere in the document: names are strings and extension entries are objects. Walked
// with an explicit stack (the depth is already bounded, but this keeps it independent of that).
void checkNamesAndExtensions(const json& doc) {
    std::vector<std::pair<const json*, std::string>> stack{{&doc, ""}};
    while (!stack.empty()) {
        auto [v, path] = stack.back();
        stack.pop_back();
        if (v->is_object()) {
            if (const json* name = member(*v, "name"); name && !name->is_string()) bad(at(path, "name"), "a string");
            if (const json* ext = member(*v, "extensions")) {
                if (!ext->is_object()) bad(at(path, "extensions"), "an object");
                for (const auto& [k, e] : ext->items())
                    if (!e.is_object()) bad(at(at(path, "extensions"), k.c_str()), "an object");
            }
            for (const auto& [k, child] : v->items())
                if (k != "extras" && (child.is_object() || child.is_array())) stack.push_back({&child, at(path, k.c_str())});
        } else if (v->is_array()) {
            for (std::size_t i = 0; i < v->size(); ++i)
                if ((*v)[i].is_object() || (*v)[i].is_array()) stack.push_back({&(*v)[i], at(path, i)});
        }
    }
}

std::uint32_t le32(const unsigned char* p) {
    return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 | std::uint32_t(p[3]) << 24;
}

// The JSON text of a .gltf, or the first (JSON) chunk of a .glb, with the GLB framing checked.
std::string_view jsonText(std::string_view bytes) {
    const auto* header = reinterpret_cast<const unsigned char*>(bytes.data());
    if (bytes.size() >= 4 && std::memcmp(header, "glTF", 4) == 0) {
        if (bytes.size() < 20) throw Problem("GLB: truncated header");
        if (le32(header + 4) != 2) throw Problem("GLB: version " + std::to_string(le32(header + 4)) + ", expected 2");
        std::uint32_t chunkLength = le32(header + 12);
        if (le32(header + 16) != 0x4E4F534Au) throw Problem("GLB: first chunk is not JSON");
        if (chunkLength > bytes.size() - 20) throw Problem("GLB: JSON chunk exceeds the file");
        return bytes.substr(20, chunkLength);
    }
    return bytes;
}

// Deep nesting is never legitimate glTF; refusing it up front protects every recursive JSON
// consumer after us (tinygltf's parser included) from stack exhaustion.
constexpr int kMaxDepth = 64;

}  // namespace

std::string checkGltfSchema(std::string_view bytes, IgnoredLog* ignored) {
    try {
        std::string_view text = jsonText(bytes);
        json doc = json::parse(text, [](int depth, json::parse_event_t, json&) {
            if (depth > kMaxDepth) throw Problem("JSON nested deeper than " + std::to_string(kMaxDepth) + " levels");
            return true;
        });
        checkDocument(doc, ignored);
        checkNamesAndExtensions(doc);
        return {};
    } catch (const Problem& p) {
        return p.what();
    } catch (const json::parse_error& e) {
        // nlohmann's message starts with "[json.exception.parse_error.101] "; keep what follows.
        std::string what = e.what();
        auto close = what.find("] ");
        return "JSON " + (close == std::string::npos ? what : what.substr(close + 2));
    } catch (const json::exception& e) {
        return std::string("JSON: ") + e.what();
    }
}

}  // namespace strata::detail
