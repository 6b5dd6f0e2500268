#pragma once
// Where the tests find the source tree and the shared models: the paths the build was configured
// with, unless STRATA_SOURCE_DIR or STRATA_SHARED_SCENES_DIR name others at run time (a test
// binary carried to another machine, such as a lent GPU: scripts/gpu_check.sh sets both).
#include <cstdlib>
#include <filesystem>

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

}  // namespace strata::test
