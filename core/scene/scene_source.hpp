#pragma once
// Opens what the command line calls SCENE: `builtin:NAME[:ARG]`, a .gltf/.glb file, a .json
// scene description, or the name of a description shipped in scenes/ ("fandisk-glass").
#include "scene/scene.hpp"

#include <string>

namespace strata {

// Throws LoadError (bad file) or std::invalid_argument (bad builtin spec), one line each.
Scene openScene(const std::string& spec);

}  // namespace strata
