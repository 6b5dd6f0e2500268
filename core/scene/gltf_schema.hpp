#pragma once
// A light schema check of a glTF file's JSON, run before tinygltf parses it. tinygltf quietly
// replaces a property of the wrong JSON type by its default (a texture index of -1, a
// pbrMetallicRoughness that is an array, a name that is a number), which would render the file
// "successfully" but wrongly; this check turns those into errors. It covers the core properties
// (types only; index ranges are checked by the loader), rejects absurd nesting depth, and
// refuses files whose extensionsRequired names an extension the loader cannot honour.
#include <string>
#include <string_view>

namespace strata::detail {

class IgnoredLog;

// `bytes` are the whole file. Returns "" when the JSON (of a .gltf, or the JSON chunk of a .glb)
// passes, otherwise one line saying what is wrong, e.g. "materials[0].pbrMetallicRoughness:
// expected an object". What only the JSON shows and tinygltf then drops without a word (a node's
// translation, rotation and scale beside its matrix) is noted in `ignored` when given.
std::string checkGltfSchema(std::string_view bytes, IgnoredLog* ignored = nullptr);

}  // namespace strata::detail
