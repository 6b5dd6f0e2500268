#include "scene/scene_source.hpp"

#include "scene/builtin_scenes.hpp"
#include "scene/gltf_loader.hpp"
#include "scene/load_error.hpp"
#include "scene/scene_description.hpp"

#include <algorithm>
#include <filesystem>

namespace strata {
namespace fs = std::filesystem;

Scene openScene(const std::string& spec, std::vector<std::string>* warnings) {
    if (spec.rfind("builtin:", 0) == 0) return makeBuiltinScene(spec.substr(8));
    fs::path path(spec);
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
    if (ext.empty()) {
        fs::path shipped = fs::path(STRATA_SCENE_DIR) / (spec + ".json");
        if (fs::exists(shipped)) return loadSceneDescription(shipped, warnings);
    }
    if (!fs::exists(path)) throw LoadError(spec + ": no such file (and not builtin:NAME or a scene in scenes/)");
    if (ext == ".gltf" || ext == ".glb") {
        GltfLoadReport report;
        Scene scene = loadGltf(path, report);
        if (warnings) warnings->insert(warnings->end(), report.warnings.begin(), report.warnings.end());
        return scene;
    }
    if (ext == ".json") return loadSceneDescription(path, warnings);
    throw LoadError(spec + ": unknown scene type '" + ext + "' (expected .gltf, .glb or .json)");
}

}  // namespace strata
