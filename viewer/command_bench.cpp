// `strata bench`: every requested technique against the exact reference on the same frames.
#include "commands.hpp"
#include "open_scene.hpp"

#include "bench/advisor.hpp"
#include "bench/bench.hpp"
#include "bench/report_folder.hpp"
#include "oit/technique.hpp"
#include "gl/context.hpp"
#include "image/image.hpp"
#include "io/atomic_file.hpp"
#include "io/interrupt.hpp"
#include "render/frame_size.hpp"
#include "lod_options.hpp"
#include "zoom_options.hpp"
#include "settings_options.hpp"
#include "oit/device_defaults.hpp"

#include <cstdio>
#include <iostream>
#include <optional>

namespace strata {
namespace {

struct BenchArgs {
    std::string scene;
    std::string modes = "all";
    std::string size = "512x512";
    int frames = 10;
    int warmup = 2;
    std::string cameraPath;
    std::string json, csv, images, report;
    SettingsArgs settings;
    ZoomArgs zoom;
    LodArgs lod;
    double depthTieUlps = -1.0;  // < 0: the scene's own (Scene::depthTieUlps)
    int referenceSupersample = 1;
    bool wall = false;
    std::string budgetPin;  // "Z,L": BenchOptions::budgetPin
};

void run(const BenchArgs& a) {
    // Outputs are written after the whole run: refuse an unwritable one before it starts.
    for (const std::string& out : {a.json, a.csv})
        if (!out.empty()) checkWritable(out);
    BenchOptions options;
    options.sceneName = a.scene;
    const bool autoMode = a.modes == "auto";
    if (!autoMode) options.modes = parseModeList(a.modes);
    options.size = parseSize(a.size);
    options.frames = a.frames;
    options.warmupFrames = a.warmup;
    // Settings are checked against every mode before the scene loads or a frame renders.
    if (autoMode && (!a.settings.set.empty() || !a.settings.preset.empty()))
        throw std::invalid_argument("--modes auto chooses the settings itself; drop --set and --settings");
    const std::vector<SettingAssignment> assignments = settingsAssignments(a.settings);
    options.settings = resolveSettings(autoMode ? allTechniqueIds() : benchModeIds(options.modes), assignments);
    if (!a.cameraPath.empty()) options.cameraPath = CameraPath::read(a.cameraPath);
    options.zoom = a.zoom.fixedZoom();
    options.zoomFilter = a.zoom.filter();
    options.referenceSupersample = a.referenceSupersample;
    options.wallFrames = a.wall;
    options.budget = a.zoom.budget();
    if (options.wallFrames && options.budget)
        throw std::invalid_argument("--wall times fixed frames; a --frame-budget-ms run chooses each frame's zoom and bound");
    if (options.budget) {
        options.zoomController = a.zoom.controllerKind();
        options.levers = a.zoom.levers(a.lod.options().mode);
        options.lodLadder.basePx = a.lod.options().maxErrorPx;
        // Checked before the scene loads and impostors bake (runBench checks again).
        if (!a.budgetPin.empty()) {
            options.budgetPin = parseBudgetPin(a.budgetPin, options.lodLadder.levels);
            checkBudgetPin(*options.budgetPin, options.budget, options.levers);
        }
    }
    if (!a.images.empty()) checkFolderCreatable(a.images);
    if (!a.report.empty()) checkFolderCreatable(a.report);
    const lod::LodOptions lodOptions = a.lod.options();
    options.progress = [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); };

    Scene scene = openSceneAndWarn(a.scene);
    if (a.depthTieUlps >= 0.0) scene.depthTieUlps = a.depthTieUlps;
    gl::HeadlessContext context;
    checkFrameSize(options.size);
    if (options.referenceSupersample > 1) checkFrameSize(options.size * options.referenceSupersample);
    GpuScene gpu(std::move(scene));
    if (!autoMode) {
        // Again, now that the device is known: its defaults first, the options over them.
        options.settings = resolveSettingsForDevice(benchModeIds(options.modes), assignments, gl::currentDeviceInfo());
    } else {
        // `--modes auto`: the advisor's pick (bench/advisor.hpp's rule with its default bound)
        // measured on this device at this size, two frames a configuration, then benched.
        const AdvisorCandidate chosen = autoPick(gpu, options, options.progress);
        options.modes = {chosen.id};
        std::vector<SettingAssignment> picked;
        for (const std::string& s : chosen.assignments) picked.push_back({chosen.id + "." + s, "--modes auto"});
        options.settings = resolveSettings(benchModeIds(options.modes), picked);
    }
    // Every output (images as they are rendered, then JSON and CSV) appears only once the whole
    // run succeeded; the images folder is made last, after every input was checked.
    OutputBatch outputs;
    std::optional<ReportFolder> reportFolder;
    if (!a.report.empty()) {
        reportFolder.emplace(outputs, a.report, options.size);
        reportFolder->attach(options);
    }
    if (!a.images.empty()) {
        outputs.createFolder(a.images);
        options.firstFrame = [&, report = options.firstFrame](const std::string& id, const Image& frame, const Image& reference) {
            writeImage(outputs, std::filesystem::path(a.images) / (id + ".png"), frame);
            if (report) report(id, frame, reference);
        };
    }
    // Level of detail: impostors baked and the cost model calibrated before the first timed frame.
    std::optional<lod::LodController> lodController;
    if (lodOptions.mode != lod::LodMode::Geometry) {
        // Every frame the run draws with stand-ins, warm-up included, over the techniques asked
        // for (an unrequested reference draws geometry).
        lod::LodOptions planned = lodOptions;
        // Under a budget with the LOD lever, raising the bound also draws stand-ins at fewer,
        // merged slices (unless --impostor-merged-slices already takes them within any bound).
        if (options.budget && options.levers.lod && !planned.mergedSlices) planned.levelBasePx = planned.maxErrorPx;
        const std::size_t modes = options.modes.empty() ? techniqueRegistry().size() : options.modes.size();
        planned.plannedFrames = (long long)modes * (options.frames + options.warmupFrames);
        lodController.emplace(gpu, planned, &std::cerr);
        lodController->select(defaultCamera(gpu.scene(), gpu.objects()), options.size, 0);  // bakes before timing
        options.lod = [&](const Camera& camera, glm::ivec2 size, int frames, double maxErrorPx) {
            BenchLodFrame frame;
            if (maxErrorPx > 0.0) lodController->setBudgetBoundPx(maxErrorPx, lodOptions.maxErrorPx);
            else lodController->setMaxErrorPx(lodOptions.maxErrorPx);
            frame.standIns = lodController->select(camera, size, frames);
            frame.impostorObjects = lodController->selection().impostorObjects;
            frame.impostorBytes = lodController->selection().impostorBytes;
            return frame;
        };
        options.lodReport = lodReport(*lodController);
        if (lodOptions.mode == lod::LodMode::Auto)
            options.lodPreview = [&](const Camera& camera, glm::ivec2 size, const std::vector<double>& bounds) {
                return lodController->previewBounds(camera, size, bounds);
            };
    } else {
        options.lodReport = {{"mode", "geometry"}};
    }
    BenchReport report = runBench(gpu, options);
    if (lodController) {
        report.lod = lodReport(*lodController);  // meshes baked during the run counted too
        std::fprintf(stderr, "%s\n", lodSummary(*lodController).c_str());
    }
    // Stopped before any technique completed: nothing to write.
    if (report.interrupted && report.modes.empty()) throw Interrupted(interruptSignal());
    std::string reportWarning;
    if (reportFolder) {
        ReportPageText text;
        text.description = "Every technique asked for against the exact reference, on this device.";
        text.command = "strata bench " + a.scene + " --modes " + a.modes + " --size " + a.size + " --frames " +
                       std::to_string(a.frames) + " --report " + a.report;
        reportWarning = reportFolder->finish(report, text);
    }
    if (!a.json.empty()) outputs.addText(a.json, benchToJson(report).dump(2) + "\n");
    if (!a.csv.empty()) outputs.addText(a.csv, benchToCsv(report));
    outputs.commit();
    std::cout << benchToTable(report);
    if (!reportWarning.empty()) std::fprintf(stderr, "%s\n", reportWarning.c_str());
    if (reportFolder)
        std::cout << "report written to " << std::filesystem::absolute(a.report).string() << "/index.html\n";
    // The completed rows are written and marked; the status still says the run did not finish.
    if (report.interrupted) throw Interrupted(interruptSignal());
}

}  // namespace

void registerBenchCommand(CLI::App& app) {
    auto args = std::make_shared<BenchArgs>();
    auto* cmd = app.add_subcommand("bench", "time and measure techniques against the exact reference");
    cmd->add_option("scene", args->scene, "builtin:NAME[:ARG], a .gltf/.glb, a .json description, or a scenes/ name")->required();
    cmd->add_option("--modes", args->modes,
                    "all, technique ids separated by commas, or auto (what `strata advise` recommends on this device)")
        ->capture_default_str();
    cmd->add_option("--size", args->size, "WxH")->capture_default_str();
    cmd->add_option("--frames", args->frames, "recorded frames per technique")->check(CLI::Range(1, 100000))->capture_default_str();
    cmd->add_option("--warmup", args->warmup, "unrecorded frames per technique")->check(CLI::Range(0, 1000))->capture_default_str();
    cmd->add_option("--camera-path", args->cameraPath, "camera path: frames are spread evenly over its duration");
    cmd->add_option("--json", args->json, "write the JSON report here");
    cmd->add_option("--csv", args->csv, "write one CSV row per technique here");
    cmd->add_option("--images", args->images, "write each technique's first frame as PNG into this folder");
    cmd->add_option("--report", args->report, "write a report folder here: index.html (chart, heatmap, contact sheet of "
                    "images and error maps, sortable table), README.md, bench.json, bench.csv, images");
    addZoomOptions(cmd, args->zoom, true, "size");
    addLodOptions(cmd, args->lod);
    cmd->add_option("--depth-tie-ulps", args->depthTieUlps,
                    "depths within this many float ulps (relative) are one layer (default: the scene's, 1024)")
        ->check(CLI::Range(0.0, 8388608.0));  // 2^23 ulps: depths within a factor of two
    cmd->add_option("--reference-supersample", args->referenceSupersample,
                    "draw the reference at N times the size each way and average it down: every row, the "
                    "reference's own included, is then compared with an antialiased frame (1..4)")
        ->check(CLI::Range(1, 4))
        ->capture_default_str();
    cmd->add_flag("--wall", args->wall,
                  "draw each technique's frames once more without pass timers or the fragment count, timed by the "
                  "wall clock to a glFinish as the peers time theirs (a 'wall ms' table, JSON wall_ms_median)");
    cmd->add_option("--budget-pin", args->budgetPin,
                    "ZOOM,LEVEL: draw every frame at this zoom and LOD ladder level instead of the budget's choice, "
                    "with the budget run's per-frame figures (scripts/bench_budget.sh --oracle)")
        ->needs(cmd->get_option("--frame-budget-ms"));
    addSettingsOptions(cmd, args->settings);
    cmd->callback([args] { run(*args); });
}

}  // namespace strata
