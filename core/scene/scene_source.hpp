#pragma once
// Opens what the command line calls SCENE: `builtin:NAME[:ARG]`, a .gltf/.glb file, a .json
// scene description, or the name of a description shipped in scenes/ ("fandisk-glass").
#include "scene/scene.hpp"

#include <string>
#include <vector>

namespace strata {

// Throws LoadError (bad file) or std::invalid_argument (bad builtin spec), one line each.
// What a glTF file holds that is not drawn as given (GltfLoadReport::warnings, one line each,
// each naming its file, no line twice) is appended to `warnings` when given, for the caller to
// print; nothing is printed here.
Scene openScene(const std::string& spec, std::vector<std::string>* warnings = nullptr);

}  // namespace strata
