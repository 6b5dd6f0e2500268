#pragma once
// The level-of-detail options, described once for `render`, `bench` and `view`:
// `--lod geometry|impostors|auto` (default auto: per object, by the cost model calibrated at
// start-up, under --lod-max-error-px) and the layered impostors' --impostor-views,
// --impostor-resolution, --impostor-slices and --impostor-overlap.
#include "lod/lod_controller.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <memory>
#include <string>

namespace strata {

// The viewer's impostor baking per frame (LodOptions::bakeBudgetMs): about one frame at 60 Hz.
inline constexpr double kViewerBakeBudgetMs = 16.0;

struct LodArgs {
    std::string mode = "auto";
    int views = 20;
    int resolution = 128;
    int slices = 64;
    float overlap = 0.5f;
    double maxErrorPx = lod::kDefaultMaxErrorPx;
    std::string cache = "default";  // "none", "default" ($XDG_CACHE_HOME/strata/impostors) or a folder
    double cacheMiB = double(lod::ImpostorCache::kDefaultMaxBytes >> 20);
    double memoryMiB = 0.0;  // 0: no cap
    bool mergedSlices = false;

    lod::LodOptions options() const;  // throws naming a bad mode
};

void addLodOptions(CLI::App* cmd, LodArgs& args);

// The LOD of an interactive window (walkthrough and immersive): baking under kViewerBakeBudgetMs
// a frame, objects drawn as geometry until their impostor is ready; progress on stderr.
std::unique_ptr<lod::LodController> makeWindowLod(const GpuScene& scene, const LodArgs& args);

// What a bench JSON's "lod" holds: the mode, the impostor settings, and once calibrated the
// cost model (lod/lod_cost_model.hpp) and the bake's time and memory.
nlohmann::json lodReport(const lod::LodController& controller);

// One line for the terminal: "lod auto: 37 of 101 objects as impostors, 1.4 MB of impostors".
std::string lodSummary(const lod::LodController& controller);

}  // namespace strata
