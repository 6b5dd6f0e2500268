#pragma once
// Opens SCENE for a command (render, bench, view, demo) and prints what its files hold that is
// not drawn as given: one line each on stderr, "strata: warning: <file>: <what was ignored>",
// before any frame is rendered. The loaders only collect these lines; printing is the commands'.
#include "scene/scene.hpp"

#include <string>

namespace strata {

Scene openSceneAndWarn(const std::string& spec);

}  // namespace strata
