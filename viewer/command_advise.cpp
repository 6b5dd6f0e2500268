// `strata advise`: the techniques measured on this device, their speed/accuracy Pareto front and
// a recommendation (bench/advisor.hpp states the rule).
#include "commands.hpp"
#include "open_scene.hpp"
#include "settings_options.hpp"

#include "bench/advisor.hpp"
#include "bench/bench.hpp"
#include "gl/context.hpp"
#include "io/atomic_file.hpp"
#include "io/interrupt.hpp"
#include "render/frame_size.hpp"

#include <cstdio>
#include <iostream>

namespace strata {
namespace {

struct AdviseArgs {
    std::string scene;
    std::string cameraPath;
    std::string size = "512x512";
    std::string modes = "all";
    double budgetMs = 0.0;
    double maxError = 0.0;
    bool noTrades = false;
    int frames = 3;
    int warmup = 1;
    std::string json;
};

void run(const AdviseArgs& a) {
    if (!a.json.empty()) checkWritable(a.json);
    const std::vector<AdvisorCandidate> candidates = advisorCandidates(parseModeList(a.modes), !a.noTrades);
    AdvisorCriteria criteria;
    if (a.budgetMs > 0.0) criteria.budgetMs = a.budgetMs;
    if (a.maxError > 0.0) criteria.maxRmse = a.maxError;
    BenchOptions base;
    base.sceneName = a.scene;
    base.size = parseSize(a.size);
    base.frames = a.frames;
    base.warmupFrames = a.warmup;
    if (!a.cameraPath.empty()) base.cameraPath = CameraPath::read(a.cameraPath);

    Scene scene = openSceneAndWarn(a.scene);
    gl::HeadlessContext context;
    checkFrameSize(base.size);
    GpuScene gpu(std::move(scene));
    std::fprintf(stderr, "advise: %zu configurations of %s at %s, %d frames each, geometry (no LOD)\n", candidates.size(),
                 a.scene.c_str(), a.size.c_str(), a.frames);
    // Under a budget, a technique whose defaults take 4 times that is not explored further.
    std::vector<AdvisorPoint> points = measureCandidates(
        gpu, candidates, base, [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); },
        criteria.budgetMs ? 4.0 * *criteria.budgetMs : 0.0);
    if (points.empty()) throw Interrupted(interruptSignal());
    const bool interrupted = interruptSignal() != 0;
    markPareto(points);
    const AdvisorPick pick = recommend(points, criteria);
    std::cout << "device: " << gl::currentDeviceInfo().renderer << "\n";
    if (interrupted)
        std::cout << "stopped by a signal: " << points.size() << " of " << candidates.size()
                  << " configurations measured; the recommendation is among those\n";
    std::cout << "\n";
    std::cout << advisorTable(points, pick) << "\n" << advisorPlot(points, pick) << "\n";
    const AdvisorPoint& chosen = points[std::size_t(pick.index)];
    std::cout << "recommended: " << chosen.candidate.label() << " (" << pick.reason << "): frame "
              << formatNumber("%.3f", chosen.frameMs) << " ms, RMSE " << formatNumber("%.2e", chosen.rmse) << "\n";
    std::string settings;
    for (const std::string& s : chosen.candidate.assignments) settings += " --set " + chosen.candidate.id + "." + s;
    std::cout << "  strata view " << a.scene << " --mode " << chosen.candidate.id << settings << "\n";
    if (!a.json.empty()) {
        nlohmann::json j = advisorToJson(points, pick, criteria);
        j["scene"] = a.scene;
        j["size"] = {base.size.x, base.size.y};
        j["frames"] = a.frames;
        j["device"] = gl::currentDeviceInfo().renderer;
        j["interrupted"] = interrupted;
        j["configurations_planned"] = candidates.size();
        OutputBatch outputs;
        outputs.addText(a.json, j.dump(2) + "\n");
        outputs.commit();
    }
    if (interruptSignal()) throw Interrupted(interruptSignal());
}

}  // namespace

void registerAdviseCommand(CLI::App& app) {
    auto args = std::make_shared<AdviseArgs>();
    auto* cmd = app.add_subcommand("advise", "measure the techniques and their speed/accuracy trades on this device, "
                                             "print the Pareto front and recommend one");
    cmd->add_option("scene", args->scene, "builtin:NAME[:ARG], a .gltf/.glb, a .json description, or a scenes/ name")->required();
    cmd->add_option("--camera-path", args->cameraPath, "camera path: frames are spread evenly over its duration");
    cmd->add_option("--size", args->size, "WxH")->capture_default_str();
    cmd->add_option("--budget-ms", args->budgetMs,
                    "frame budget: recommend the most accurate configuration whose frame fits it (the trades of a "
                    "technique whose defaults take 4 times the budget are not measured)")
        ->check(CLI::PositiveNumber & CLI::Range(0.0, 1e6));
    cmd->add_option("--max-error", args->maxError,
                    "RMSE bound (linear RGB): recommend the fastest configuration within it (default 1/255)")
        ->check(CLI::PositiveNumber & CLI::Range(0.0, 1.0));
    cmd->add_option("--modes", args->modes, "all, or technique ids separated by commas")->capture_default_str();
    cmd->add_flag("--no-trades", args->noTrades, "measure each technique at its defaults only");
    cmd->add_option("--frames", args->frames, "recorded frames per configuration")->check(CLI::Range(1, 1000))->capture_default_str();
    cmd->add_option("--warmup", args->warmup, "unrecorded frames per configuration")->check(CLI::Range(0, 100))->capture_default_str();
    cmd->add_option("--json", args->json, "write every configuration, the front and the recommendation here");
    cmd->callback([args] { run(*args); });
}

}  // namespace strata
