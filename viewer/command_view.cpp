// `strata view`: the interactive viewer.
#include "commands.hpp"

#include "open_scene.hpp"
#include "oit/technique.hpp"
#include "settings_options.hpp"
#include "view_app.hpp"

#include "bench/advisor.hpp"
#include "bench/bench.hpp"
#include "gl/context.hpp"
#include "io/interrupt.hpp"
#include "io/parse_integers.hpp"
#include "io/printable.hpp"
#include "render/frame_size.hpp"

#include <cstdio>
#include <stdexcept>

namespace strata {
namespace {

// "X,Y": a window pixel from the top-left, inside the window of `size`.
glm::ivec2 parseInspectPixel(const std::string& text, glm::ivec2 size) {
    const auto xy = parseIntPair(text, ",");
    if (!xy) throw std::invalid_argument("--inspect: expected X,Y (two integers), got '" + printable(text, 40) + "'");
    const int x = xy->first, y = xy->second;
    if (x < 0 || y < 0 || x >= size.x || y >= size.y)
        throw std::invalid_argument("--inspect: pixel " + std::to_string(x) + "," + std::to_string(y) +
                                    " is outside the " + std::to_string(size.x) + "x" + std::to_string(size.y) + " window");
    return {x, y};
}

// `--mode auto`: the advisor's pick under its default bound (bench/advisor.hpp), two frames a
// configuration at the window's size, in a headless context of its own.
AdvisorCandidate adviseTechnique(const std::string& sceneSpec, glm::ivec2 size) {
    Scene scene = openSceneAndWarn(sceneSpec);
    gl::HeadlessContext context;
    checkFrameSize(size);
    GpuScene gpu(std::move(scene));
    BenchOptions base;
    base.sceneName = sceneSpec;
    base.size = size;
    std::fprintf(stderr, "--mode auto: measuring every technique and its trades at %dx%d\n", size.x, size.y);
    return autoPick(gpu, base, [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); });
}

}  // namespace

void registerViewCommand(CLI::App& app) {
    auto options = std::make_shared<ViewOptions>();
    auto size = std::make_shared<std::string>("1280x800");
    auto play = std::make_shared<std::string>();
    auto record = std::make_shared<std::string>();
    auto trace = std::make_shared<std::string>();
    auto screenshot = std::make_shared<std::string>();
    auto* cmd = app.add_subcommand("view", "open the interactive viewer");
    cmd->add_option("scene", options->scene, "scene to open")->capture_default_str();
    cmd->add_option("--mode", options->mode,
                    "technique id, or auto: what `strata advise` recommends for this scene at this size, measured "
                    "before the window opens")
        ->capture_default_str();
    auto view = std::make_shared<std::string>(viewName(ViewKind::Image));
    std::vector<std::string> viewNames;
    for (ViewKind v : kViewKinds) viewNames.push_back(viewName(v));
    cmd->add_option("--view", *view,
                    "what the window shows first: image, heatmap (coplanarity), error (against abuffer), split (A | B)")
        ->check(CLI::IsMember(viewNames))
        ->capture_default_str();
    cmd->add_option("--split-with", options->splitWith, "split view: technique B, right of the divider")
        ->capture_default_str();
    cmd->add_option("--split-at", options->splitAt, "split view: the divider, 0..1 of the width")
        ->check(CLI::Range(0.0f, 1.0f))
        ->capture_default_str();
    auto inspect = std::make_shared<std::string>();
    cmd->add_option("--inspect", *inspect, "list the fragments at window pixel X,Y (from the top-left), as a click does");
    auto settings = std::make_shared<SettingsArgs>();
    addSettingsOptions(cmd, *settings);
    cmd->add_option("--path", *play, "play this camera path");
    cmd->add_option("--record", *record, "record the camera to this path file (R toggles)");
    // Options that only act with another are refused without it rather than ignored.
    auto* immersive = cmd->add_flag("--immersive", options->immersive, "head-tracked mode driven by --trace");
    cmd->add_option("--trace", *trace, "head-pose trace for --immersive");
    cmd->add_option("--predictor", options->predictor, "immersive: none, cv, desp, kalman (adaptive), kalman-fixed, kalman-cv")
        ->capture_default_str()
        ->needs(immersive);
    cmd->add_option("--deflect", options->deflect, "immersive: none, shift, homography")->capture_default_str()->needs(immersive);
    cmd->add_flag("--stereo", options->stereo, "immersive: side-by-side stereo")->needs(immersive);
    cmd->add_option("--ipd", options->ipdMm, "immersive: interpupillary distance, mm")->capture_default_str()->needs(immersive);
    cmd->add_option("--extra-latency", options->extraLatencyMs, "immersive: ms added to the measured frame time")
        ->capture_default_str()
        ->needs(immersive);
    auto* exitAfter =
        cmd->add_option("--exit-after-frames", options->exitAfterFrames, "render N frames, then exit (smoke tests)");
    cmd->add_option("--screenshot", *screenshot, "with --exit-after-frames: save the window here (.png)")->needs(exitAfter);
    cmd->add_option("--size", *size, "window size WxH")->capture_default_str();
    addZoomOptions(cmd, options->zoom, true, "window");
    addLodOptions(cmd, options->lod);
    cmd->callback([=] {
        glm::ivec2 s = parseSize(*size);
        const bool autoMode = options->mode == "auto";
        if (autoMode && (!settings->set.empty() || !settings->preset.empty()))
            throw std::invalid_argument("--mode auto chooses the settings itself; drop --set and --settings");
        if (!autoMode && !findTechnique(options->mode)) createTechnique(options->mode);  // throws the list of known ids
        if (!findTechnique(options->splitWith)) createTechnique(options->splitWith);
        if (!inspect->empty()) options->inspect = parseInspectPixel(*inspect, s);
        // Against every technique: the panel can switch to any of them.
        options->settingAssignments = settingsAssignments(*settings);
        resolveSettings(allTechniqueIds(), options->settingAssignments);  // a bad --set fails before a window opens
        options->view = *parseView(*view);  // checked by CLI::IsMember above
        options->zoom.fixedZoom();  // throws naming a bad --zoom before a window opens
        options->lod.options();     // and a bad impostor setting
        options->zoom.levers(options->lod.options().mode);  // and a LOD lever with no auto LOD
        if (autoMode) {
            // Measured headless on this device once everything else is checked, before the window
            // opens (the panel can switch later).
            const AdvisorCandidate pick = adviseTechnique(options->scene, s);
            options->mode = pick.id;
            std::vector<SettingAssignment> chosen;
            for (const std::string& a : pick.assignments) chosen.push_back({pick.id + "." + a, "--mode auto"});
            // As measured: no device default on top of the advisor's pick.
            options->settingAssignments = chosen;
            options->deviceDefaults = false;
        }
        options->width = s.x;
        options->height = s.y;
        if (!play->empty()) options->playPath = *play;
        if (!record->empty()) options->recordPath = *record;
        if (!trace->empty()) options->trace = *trace;
        if (!screenshot->empty()) options->screenshot = *screenshot;
        int rc = runViewer(*options);
        if (rc != 0) throw std::runtime_error("viewer exited with status " + std::to_string(rc));
    });
}

}  // namespace strata
