#include "lod_options.hpp"

#include <algorithm>
#include <cstdio>
#include <functional>
#include <map>
#include <iostream>

namespace strata {

lod::LodOptions LodArgs::options() const {
    lod::LodOptions o;
    o.mode = lod::parseLodMode(mode);
    o.maxErrorPx = maxErrorPx;
    o.impostor.views = views;
    o.impostor.resolution = resolution;
    o.impostor.slices = slices;
    o.impostor.overlap = overlap;
    o.mergedSlices = mergedSlices;
    if (cache == "default") o.impostorCache = lod::defaultImpostorCacheFolder();  // empty without a home: none
    else if (cache != "none") o.impostorCache = cache;
    o.impostorCacheMaxBytes = std::uint64_t(cacheMiB * double(1 << 20));
    o.impostorMemoryBytes = std::uint64_t(memoryMiB * double(1 << 20));
    return o;
}

void addLodOptions(CLI::App* cmd, LodArgs& args) {
    cmd->add_option("--lod", args.mode,
                    "per-object level of detail: geometry, impostors (layered impostors wherever the eye is "
                    "outside 2 bounding radii), or auto (the cheaper by the cost model, under --lod-max-error-px)")
        ->check(CLI::IsMember({"geometry", "impostors", "auto"}))
        ->capture_default_str();
    cmd->add_option("--lod-max-error-px", args.maxErrorPx, "auto: the largest impostor error accepted, pixels")
        ->check(CLI::Range(0.0, 1e6))
        ->capture_default_str();
    cmd->add_option("--impostor-views", args.views, "baked view directions per impostor: 12, 20 or 32")
        ->check(CLI::IsMember({12, 20, 32}))
        ->capture_default_str();
    cmd->add_option("--impostor-resolution", args.resolution, "texels a side of each baked view (1..256)")
        ->check(CLI::Range(1, 256))
        ->capture_default_str();
    cmd->add_option("--impostor-slices", args.slices, "depth slices per view (1..256)")
        ->check(CLI::Range(1, 256))
        ->capture_default_str();
    cmd->add_option("--impostor-overlap", args.overlap,
                    "slice widths each slice's depth interval reaches into its neighbours' (opaque only)")
        ->check(CLI::Range(0.0, 16.0))
        ->capture_default_str();
    cmd->add_flag("--impostor-merged-slices", args.mergedSlices,
                  "auto may draw far stand-ins with fewer, merged slices where the error bound allows (off by default: "
                  "a per-object bound in pixels does not hold a PSNR; a frame budget's LOD lever uses them anyway)");
    cmd->add_option("--impostor-cache", args.cache,
                    "where baked impostors are kept between runs, keyed by what they bake: none, default "
                    "($XDG_CACHE_HOME/strata/impostors, else ~/.cache/strata/impostors) or a folder")
        ->capture_default_str();
    cmd->add_option("--impostor-memory-mb", args.memoryMiB,
                    "the most impostor memory held at once (0: no cap): the most useful are baked first, the "
                    "least useful evicted, and their objects draw geometry")
        ->check(CLI::Range(0.0, 1e7))
        ->capture_default_str();
    cmd->add_option("--impostor-cache-mb", args.cacheMiB,
                    "the cache folder's cap (0: none): past it the least recently used impostors are removed")
        ->check(CLI::Range(0.0, 1e7))
        ->capture_default_str();
}

namespace {

// The LOD units drawn as stand-ins, by the slices their level of merged slices draws (level l:
// the baked count halved l times), fewest slices last.
std::map<int, int, std::greater<int>> standInsBySlices(const lod::LodController& controller) {
    std::map<int, int, std::greater<int>> counts;
    for (const lod::LodDecision& d : controller.unitSelection().objects)
        if (d.impostor) ++counts[std::max(1, controller.options().impostor.slices >> d.level)];
    return counts;
}

}  // namespace

nlohmann::json lodReport(const lod::LodController& controller) {
    const lod::LodOptions& o = controller.options();
    nlohmann::json j = {
        {"mode", lod::to_string(o.mode)},
        {"max_error_px", o.maxErrorPx},
        {"views", o.impostor.views},
        {"resolution", o.impostor.resolution},
        {"slices", o.impostor.slices},
        {"overlap", o.impostor.overlap},
        {"merged_slices", o.mergedSlices},
        // > 0: the budget's LOD lever takes coarser levels only above this bound (0: none, or
        // with merged_slices any level within the bound).
        {"level_base_px", o.levelBasePx},
        {"impostor_cache", o.impostorCache.string()},
        // The last frame's LOD units, predicted by the cost model (what LOD draws, not the frame:
        // objects in no unit, the technique and the enlargement are not in it).
        {"predicted_ms", controller.selection().predictedMs},
        {"geometry_only_predicted_ms", controller.selection().geometryOnlyMs},
    };
    // The last frame's stand-ins by the slices they drew (levels of merged slices).
    nlohmann::json bySlices = nlohmann::json::object();
    for (const auto& [slices, units] : standInsBySlices(controller)) bySlices[std::to_string(slices)] = units;
    j["stand_ins_by_slices"] = bySlices;
    if (const lod::ImpostorSet* set = controller.impostors()) {
        const lod::ImpostorMemory m = set->bytes();
        j["baked_impostors"] = set->bakedImpostors();  // one per mesh, or per mesh and material where the bake keeps its texture
        j["bakes_declined"] = controller.bakeDecisions().declined;  // would not pay over the frames planned
        j["declined_bake_ms"] = controller.bakeDecisions().declinedBakeMs;
        j["bake_ms"] = set->bakeMs();
        j["loaded_impostors"] = set->loadedImpostors();  // of baked_impostors, loaded from the cache
        j["evicted_impostors"] = set->evictedImpostors();  // by the memory cap (memory_cap_bytes, 0: none)
        j["memory_cap_bytes"] = o.impostorMemoryBytes;
        j["image_bytes"] = m.images;
        j["rectangle_bytes"] = m.rectangles;
        j["vertex_bytes"] = m.vertexBuffer;
    }
    if (const lod::ImpostorCache* cache = controller.cache()) {
        const lod::ImpostorCacheCounts& c = cache->counts();
        j["cache"] = {{"hits", c.hits}, {"misses", c.misses}, {"stores", c.stores}, {"evicted", c.evicted},
                      {"unreadable", c.unreadable}, {"load_ms", c.loadMs}};
    }
    if (const auto& c = controller.calibration()) {
        j["model"] = {{"geometry_fixed_ms", c->model.geometryFixedMs},
                      {"geometry_ms_per_megatriangle", c->model.geometryMsPerMegatriangle},
                      {"geometry_ms_per_megapixel", c->model.geometryMsPerMegapixel},
                      {"impostor_fixed_ms", c->model.impostorFixedMs},
                      {"impostor_instance_ms", c->model.impostorInstanceMs},
                      {"impostor_ms_per_kiloquad", c->model.impostorMsPerKiloquad},
                      {"impostor_ms_per_kiloside_px", c->model.impostorMsPerKilosidePx},
                      {"impostor_ms_per_megapixel", c->model.impostorMsPerMegapixel},
                      {"calibration_ms", c->wallMs},
                      {"kept", c->kept}};  // from an earlier run on this device (lod/lod_cost_cache.hpp)
    }
    return j;
}

std::string lodSummary(const lod::LodController& controller) {
    const lod::LodSelection& s = controller.selection();
    // Appended piece by piece: a long line (large counts, many frames) is never cut or overrun.
    std::string line;
    auto add = [&line](const char* format, auto... values) {
        char piece[256];
        std::snprintf(piece, sizeof piece, format, values...);
        line += piece;
    };
    add("lod %s: %d of %zu objects as impostors (%d distinct), %.2f MB of impostors", lod::to_string(controller.options().mode),
        s.impostorObjects, s.objects.size(), s.impostorsUsed, double(s.impostorBytes) / 1e6);
    // Where parts are decided together (a scene description's model instances), the units too.
    const lod::LodSelection& units = controller.unitSelection();
    bool grouped = false;
    for (const lod::LodUnit& unit : controller.units().units) grouped = grouped || unit.objects.size() > 1;
    if (grouped) {
        int impostorUnits = 0;
        for (const lod::LodDecision& d : units.objects) impostorUnits += d.impostor ? 1 : 0;
        add("; %d of %zu LOD units", impostorUnits, units.objects.size());
    }
    if (const auto bySlices = standInsBySlices(controller); bySlices.size() > 1 ||
                                                             (bySlices.size() == 1 && bySlices.begin()->first != controller.options().impostor.slices)) {
        line += "; stand-ins by slices drawn:";
        for (const auto& [slices, units] : bySlices) add(" %d at %d", units, slices);
    }
    if (const lod::ImpostorSet* set = controller.impostors(); set && set->bakedImpostors() > 0)
        add("; %d impostors baked (%d from the cache) in %.0f ms", set->bakedImpostors(), set->loadedImpostors(), set->bakeMs());
    if (const lod::ImpostorSet* set = controller.impostors(); set && set->pendingBakes() > 0)
        add("; %d waiting to bake (geometry until then)", set->pendingBakes());
    if (const lod::ImpostorSet* set = controller.impostors(); set && set->evictedImpostors() > 0)
        add("; %d evicted by the %.2f MB cap", set->evictedImpostors(), double(controller.options().impostorMemoryBytes) / 1e6);
    if (const lod::LodBakeDecisions d = controller.bakeDecisions(); d.declined > 0)
        add("; %d not baked: predicted bake %.0f ms > %.0f ms saved over the %lld frames planned", d.declined, d.declinedBakeMs,
            d.declinedSavingMs, controller.options().plannedFrames);
    if (const auto& c = controller.calibration(); c && c->device == "given")
        line += "; cost model given";
    else if (c && c->kept)
        line += "; cost model kept from an earlier run";
    else if (c)
        add("; cost model calibrated in %.0f ms", c->wallMs);
    return line;
}

std::unique_ptr<lod::LodController> makeWindowLod(const GpuScene& scene, const LodArgs& args) {
    lod::LodOptions options = args.options();
    options.bakeBudgetMs = kViewerBakeBudgetMs;
    // The levels of merged slices are built for the frame budget's LOD lever, which a window can
    // turn on at any time; at the user's bound they draw nothing (LodOptions::levelBasePx).
    if (!options.mergedSlices) options.levelBasePx = options.maxErrorPx;
    return std::make_unique<lod::LodController>(scene, options, &std::cerr);
}

}  // namespace strata
