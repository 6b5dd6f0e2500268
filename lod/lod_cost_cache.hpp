#pragma once
// The calibrated LOD cost model kept between runs (issue 23: "baking costs nothing twice"; the
// calibration is the rest of what a second run with the default LOD repeats): one JSON file in
// the impostor cache's folder, keyed by the device (GL_RENDERER and GL_VERSION) and by
// kCostModelVersion, which changes whenever calibration measures something else. A file for
// another device or version, or one that does not parse into finite non-negative coefficients,
// is ignored and overwritten by the next calibration.
#include "lod/lod_cost_model.hpp"

#include <filesystem>
#include <optional>
#include <string>

namespace strata::lod {

inline constexpr int kCostModelVersion = 2;  // 2: stand-ins' share of a draw, quads and sides
inline constexpr const char* kCostModelFile = "lod-cost-model.json";

// GL_RENDERER and GL_VERSION of the current context, the key a kept model is valid for.
std::string currentDeviceKey();

// The model kept in `file` for `deviceKey`, or none (absent, another device or version,
// unreadable). Its device is the key's renderer part; wallMs is 0 (nothing was measured).
std::optional<LodCalibration> loadCostModel(const std::filesystem::path& file, const std::string& deviceKey);

// Keeps `calibration`'s model for `deviceKey` in `file`, atomically. A failure (a read-only
// disk) is not the run's: it returns false and the next run calibrates again.
bool storeCostModel(const std::filesystem::path& file, const std::string& deviceKey, const LodCalibration& calibration);

}  // namespace strata::lod
