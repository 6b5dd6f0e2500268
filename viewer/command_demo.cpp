// `strata demo`: the main job on the built-in default scene. With a display it opens the
// viewer; without one it benchmarks every technique and writes a report folder (an HTML page
// with the chart, heatmap and contact sheet: bench/report_folder.hpp).
#include "commands.hpp"
#include "open_scene.hpp"

#include "bench/bench.hpp"
#include "bench/report_folder.hpp"
#include "gl/context.hpp"
#include "image/image.hpp"
#include "io/atomic_file.hpp"
#include "io/interrupt.hpp"
#include "render/frame_size.hpp"
#include "view_app.hpp"

#include <cstdio>
#include <iostream>

namespace strata {
namespace {

struct DemoArgs {
    std::string out = "strata-demo-report";
    std::string size = "640x400";
    int frames = 5;
    bool headless = false;
};

void writeReport(const DemoArgs& a) {
    namespace fs = std::filesystem;
    fs::path dir = a.out;
    BenchOptions options;
    options.sceneName = "builtin:default";
    options.size = parseSize(a.size);
    options.frames = a.frames;
    options.warmupFrames = 1;
    options.progress = [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); };
    checkFolderCreatable(dir);

    gl::HeadlessContext context;
    checkFrameSize(options.size);
    GpuScene gpu(openSceneAndWarn(options.sceneName));
    // The report folder is made once every input was checked, and is removed again (with every
    // file in it) when the run fails: the report appears whole or not at all.
    OutputBatch outputs;
    ReportFolder folder(outputs, dir, options.size);
    folder.attach(options);
    BenchReport report = runBench(gpu, options);
    // The demo's report is whole or absent: an interrupted run leaves nothing (the batch unwinds).
    if (report.interrupted) throw Interrupted(interruptSignal());
    ReportPageText text;
    text.title = "Strata demo report";
    text.description =
        "Scene builtin:default: interpenetrating glass, a decal on a transparent panel in front of coloured glass behind "
        "glass, a stained-glass pane, a foliage card, a wireframe over its own surface, volumes, dense opaque detail "
        "behind. Every technique against the exact reference; the volumetric family against its own (abuffer-volume, "
        "which integrates the volumes as media). Techniques whose filters column in strata modes says scalar draw the "
        "coloured glass grey (its tint lost): part of their error here.";
    text.command = "strata demo --headless --size " + a.size + " --frames " + std::to_string(a.frames);
    const std::string warning = folder.finish(report, text);
    outputs.commit();
    std::cout << benchToTable(report);
    if (!warning.empty()) std::fprintf(stderr, "%s\n", warning.c_str());
    std::cout << "\nreport written to " << fs::absolute(dir).string() << "/: open index.html (README.md, bench.json, "
              << "bench.csv, images/ beside it)\n";
}

}  // namespace

void registerDemoCommand(CLI::App& app) {
    auto args = std::make_shared<DemoArgs>();
    auto* cmd = app.add_subcommand("demo", "the main job on the built-in default scene (viewer, or a report headless)");
    auto* out = cmd->add_option("--out", args->out, "report folder when headless")->capture_default_str();
    auto* size = cmd->add_option("--size", args->size, "report image size WxH")->capture_default_str();
    auto* frames =
        cmd->add_option("--frames", args->frames, "frames per technique")->check(CLI::Range(1, 1000))->capture_default_str();
    cmd->add_flag("--headless", args->headless, "write the report even when a display is present");
    cmd->callback([args, out, size, frames] {
        if (!args->headless && displayAvailable()) {
            // The report's options mean nothing to the viewer: refused, not ignored.
            for (const CLI::Option* o : {out, size, frames})
                if (o->count() > 0)
                    throw std::runtime_error("demo: " + o->get_name() + " is for the report; add --headless (a display was found, so the viewer would open)");
            ViewOptions view;
            view.scene = "builtin:default";
            runViewer(view);
            return;
        }
        writeReport(*args);
    });
}

}  // namespace strata
