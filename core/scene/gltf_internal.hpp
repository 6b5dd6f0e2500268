#pragma once
// What the glTF loader's parts share (gltf_loader.cpp, gltf_accessors.cpp, gltf_textures.cpp):
// the error they throw, and the checked reading of numbers from the document. Internal to the
// loader; loadGltf turns a GltfError into LoadError("<file>: <what>").
#include <tiny_gltf.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace strata::detail {

struct GltfError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

[[noreturn]] inline void fail(const std::string& what) { throw GltfError(what); }

inline std::string str(std::size_t v) { return std::to_string(v); }
inline std::string str(int v) { return std::to_string(v); }

// A float from a glTF number: finite as a double is not enough (1e308 becomes inf as a float).
inline float toFloat(double v, const std::string& what) {
    if (!std::isfinite(v)) fail(what + " is not finite");
    if (!std::isfinite(float(v))) {
        char text[32];
        std::snprintf(text, sizeof text, "%g", v);
        fail(what + " " + text + " does not fit a float");
    }
    return float(v);
}

// The number `key` of a JSON object (an extension's), or `fallback` where it is absent.
inline double number(const tinygltf::Value& obj, const char* key, double fallback, const std::string& what) {
    if (!obj.IsObject() || !obj.Has(key)) return fallback;
    const tinygltf::Value& v = obj.Get(key);
    if (!v.IsNumber()) fail(what + ": " + key + " is not a number");
    return v.GetNumberAsDouble();
}

}  // namespace strata::detail
