// `strata demo`: the main job on the built-in default scene. With a display it opens the
// viewer; without one it benchmarks every technique and writes a short report to a folder.
#include "commands.hpp"
#include "open_scene.hpp"

#include "bench/bench.hpp"
#include "gl/context.hpp"
#include "image/image.hpp"
#include "io/atomic_file.hpp"
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
    checkFolderCreatable(dir / "images");

    gl::HeadlessContext context;
    checkFrameSize(options.size);
    GpuScene gpu(openSceneAndWarn(options.sceneName));
    // The report folder is made once every input was checked, and is removed again (with every
    // file in it) when the run fails: the report appears whole or not at all.
    OutputBatch outputs;
    outputs.createFolder(dir / "images");
    options.firstFrame = [&](const std::string& id, const Image& frame) {
        writeImage(outputs, dir / "images" / (id + ".png"), frame);
    };
    BenchReport report = runBench(gpu, options);
    std::string table = benchToTable(report);
    outputs.addText(dir / "bench.json", benchToJson(report).dump(2) + "\n");
    outputs.addText(dir / "bench.csv", benchToCsv(report));

    std::string md =
        "# Strata demo report\n\nScene `builtin:default` (interpenetrating glass, a decal on a transparent panel in "
        "front of coloured glass behind glass, a stained-glass pane, a foliage card, a wireframe over its own surface, "
        "volumes, dense opaque detail behind), every technique against the exact reference `abuffer`. The techniques "
        "whose `strata modes` filters column says `scalar` draw the coloured glass grey (its tint lost): part of their "
        "error here. Produced by `strata demo` without a display.\n\n```\n" + table + "```\n\n";
    for (const auto& m : report.modes) md += "![" + m.id + "](images/" + m.id + ".png)\n";
    outputs.addText(dir / "README.md", md);
    outputs.commit();
    std::cout << table << "\nreport written to " << fs::absolute(dir).string() << "/ (README.md, bench.json, "
              << "bench.csv, images/)\n";
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
