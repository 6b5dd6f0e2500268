#include "open_scene.hpp"

#include "scene/scene_source.hpp"

#include <cstdio>
#include <vector>

namespace strata {

Scene openSceneAndWarn(const std::string& spec) {
    std::vector<std::string> warnings;
    Scene scene = openScene(spec, &warnings);
    for (const std::string& line : warnings) std::fprintf(stderr, "strata: warning: %s\n", line.c_str());
    return scene;
}

}  // namespace strata
