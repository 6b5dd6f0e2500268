#pragma once
// Where the tests find the source tree and the shared models: the paths the build was configured
// with, unless STRATA_SOURCE_DIR or STRATA_SHARED_SCENES_DIR name others at run time (a test
// binary carried to another machine, such as a lent GPU: scripts/gpu_check.sh sets both).
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace strata::test {

inline std::filesystem::path pathFromEnv(const char* name, const char* configured) {
    const char* value = std::getenv(name);
    return value && *value ? std::filesystem::path(value) : std::filesystem::path(configured);
}

// The repository root (scenes/, tests/shaders/, core/).
inline std::filesystem::path sourceDir() { return pathFromEnv("STRATA_SOURCE_DIR", STRATA_SOURCE_DIR); }

// ../shared/scenes-data: the real models; tests that need them skip where it is absent.
inline std::filesystem::path sharedScenesDir() {
    return pathFromEnv("STRATA_SHARED_SCENES_DIR", STRATA_SHARED_SCENES_DIR);
}

// A scene file of scenes/ whose models are named as ../../shared/scenes-data/...: the file itself
// where that is where the models are, else a copy (in the temporary directory) naming them in
// sharedScenesDir(), as on a GPU machine where STRATA_SHARED_SCENES_DIR points into a bundle.
inline std::filesystem::path sceneWithSharedModels(const std::string& name) {
    namespace fs = std::filesystem;
    const fs::path file = sourceDir() / "scenes" / name;
    const std::string named = "../../shared/scenes-data/";
    std::error_code ec;
    if (fs::equivalent(file.parent_path() / named, sharedScenesDir(), ec)) return file;
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    std::string json = text.str();
    const std::string there = fs::absolute(sharedScenesDir()).generic_string() + "/";
    for (std::size_t at = json.find(named); at != std::string::npos; at = json.find(named, at + there.size()))
        json.replace(at, named.size(), there);
    const fs::path copy = fs::temp_directory_path() / ("strata-test-" + name);
    std::ofstream(copy) << json;
    return copy;
}

}  // namespace strata::test
