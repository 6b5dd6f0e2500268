// `strata render`: one frame of a scene with one technique, headless, to PNG or EXR.
#include "commands.hpp"
#include "open_scene.hpp"

#include "camera/camera_path.hpp"
#include "gl/context.hpp"
#include "gl/debug.hpp"
#include "io/interrupt.hpp"
#include "io/atomic_file.hpp"
#include "oit/technique.hpp"
#include "oit/technique_settings.hpp"
#include "render/coplanarity.hpp"
#include "render/frame_size.hpp"
#include "lod_options.hpp"
#include "zoom_options.hpp"
#include "frame/frame_renderer.hpp"
#include "settings_options.hpp"
#include "oit/device_defaults.hpp"

#include <cstdio>
#include <optional>

namespace strata {
namespace {

struct RenderArgs {
    std::string scene;
    std::string mode = "abuffer";
    std::string size = "800x600";
    std::string cameraPath;
    double time = 0.0;
    std::string out;
    std::string heatmap;
    std::string highlight;
    SettingsArgs settings;
    ZoomArgs zoom;
    LodArgs lod;
    double depthTieUlps = -1.0;  // < 0: the scene's own (Scene::depthTieUlps)
};

void run(const RenderArgs& a) {
    glm::ivec2 size = parseSize(a.size);
    const int zoom = a.zoom.fixedZoom();
    if (!findTechnique(a.mode)) createTechnique(a.mode);  // throws the list of known ids
    const std::vector<SettingAssignment> assignments = settingsAssignments(a.settings);
    resolveSettings({a.mode}, assignments);  // a bad --set fails before the scene loads
    const lod::LodOptions lodOptions = a.lod.options();
    // Images are written after the frame: refuse an unwritable destination before rendering.
    checkImageWritable(a.out);
    if (!a.heatmap.empty()) checkImageWritable(a.heatmap);
    if (!a.highlight.empty()) checkImageWritable(a.highlight);
    if (!a.highlight.empty() && zoom > 1)
        throw std::invalid_argument("--highlight-coplanar needs the frame at its size: drop --zoom");
    Scene scene = openSceneAndWarn(a.scene);
    if (a.depthTieUlps >= 0.0) scene.depthTieUlps = a.depthTieUlps;
    gl::HeadlessContext context;
    checkFrameSize(size);  // before the scene is uploaded or a target allocated
    GpuScene gpu(std::move(scene));
    const SettingsById settings = resolveSettingsForDevice({a.mode}, assignments, gl::currentDeviceInfo());
    auto technique = createConfiguredTechnique(a.mode, settings);
    Camera camera = defaultCamera(gpu.scene(), gpu.objects());
    if (!a.cameraPath.empty()) {
        camera = cameraAt(CameraPath::read(a.cameraPath), a.time, camera);
        camera.fitClipPlanes(gpu.bounds());
    }
    FrameRenderer renderer;
    FrameOptions options;
    options.countFragments = true;
    // The heatmap comes from the GPU detector on the same frame (oit/coplanarity_detector.hpp).
    options.detectCoplanarity = !a.heatmap.empty() || !a.highlight.empty();
    options.zoom = zoom;
    options.zoomFilter = a.zoom.filter();
    std::optional<lod::LodController> lodController;
    if (lodOptions.mode != lod::LodMode::Geometry) {
        // Quiet: one frame's bake and calibration are summed up in the summary line below.
        lod::LodOptions oneFrame = lodOptions;
        oneFrame.plannedFrames = 1;  // a bake pays only if this frame saves more than it costs
        lodController.emplace(gpu, oneFrame, nullptr);
        options.standIns = lodController->select(camera, size);
    }
    FrameResult result = renderer.render(gpu, camera, size, technique.get(), options);
    gl::checkGl("render");
    Image image = renderer.readOutput();
    gl::checkGl("read back");
    Image heat, highlighted;
    if (result.coplanarity) {
        // Of the frame drawn: at a zoom, the reduced one.
        const std::vector<std::uint32_t> largest = renderer.coplanarity()->readPixels().largestLayer;
        heat = coplanarityHeatmap(largest, result.renderSize.x, result.renderSize.y);
        if (!a.highlight.empty()) highlighted = coplanarityHighlight(image, largest);
        gl::checkGl("coplanarity read back");
    }
    // The image and its heatmap appear together or not at all; a signal during the frame or its
    // bake stops here, before anything is written.
    throwIfInterrupted();
    OutputBatch outputs;
    writeImage(outputs, a.out, image);
    if (!a.heatmap.empty()) writeImage(outputs, a.heatmap, heat);
    if (!a.highlight.empty()) writeImage(outputs, a.highlight, highlighted);
    outputs.commit();
    const auto& s = result.stats;
    const std::string zoomed = zoom > 1 ? " (drawn at " + std::to_string(result.renderSize.x) + "x" +
                                              std::to_string(result.renderSize.y) + ", zoom " + std::to_string(zoom) + ")"
                                        : "";
    std::printf("%s: %s %dx%d%s, %.3f ms GPU (%d passes), %llu of %llu fragments%s\n", a.out.c_str(), a.mode.c_str(),
                size.x, size.y, zoomed.c_str(), result.gpuMs, s.passes, (unsigned long long)s.fragmentsCaptured,
                (unsigned long long)result.fragmentsTotal.value_or(0), s.overflowed ? ", OVERFLOWED" : "");
    if (lodController) std::printf("  %s\n", lodSummary(*lodController).c_str());
    for (const auto& p : result.passTimes)
        std::printf("  %-20s %9.3f ms GPU %9.3f ms CPU\n", p.name.c_str(), p.gpuMs, p.cpuMs);
    if (result.coplanarity) {
        const CoplanarityStats& c = *result.coplanarity;
        const std::uint64_t total = result.fragmentsTotal.value_or(0);
        std::printf("%s: coplanarity C_p %.4f (%llu of %llu pixels with fragments share a layer), R_h %s %.4f, "
                    "R_h one fragment per layer (f2b) %.4f; detector %.3f ms GPU\n",
                    (a.heatmap.empty() ? a.highlight : a.heatmap).c_str(), c.coplanarityProbability(), (unsigned long long)c.pixelsWithTies(),
                    (unsigned long long)c.pixelsWithFragments(), a.mode.c_str(),
                    total ? double(s.fragmentsCaptured) / double(total) : 1.0, c.oneFragmentPerLayerRobustness(),
                    result.coplanarityMs);
        std::printf("  pixels by largest layer:");
        for (int k = 0; k < kCoplanarityBins; ++k)
            std::printf(" %s%d %llu", k == kCoplanarityBins - 1 ? ">=" : "", k,
                        (unsigned long long)c.pixelsByLargestLayer[std::size_t(k)]);
        std::printf("\n");
    }
}

}  // namespace

void registerRenderCommand(CLI::App& app) {
    auto args = std::make_shared<RenderArgs>();
    auto* cmd = app.add_subcommand("render", "render one frame headless to .png or .exr");
    cmd->add_option("scene", args->scene, "builtin:NAME[:ARG], a .gltf/.glb, a .json description, or a scenes/ name")->required();
    cmd->add_option("--mode", args->mode, "technique id (see `strata modes`)")->capture_default_str();
    cmd->add_option("--size", args->size, "WxH")->capture_default_str();
    auto* path = cmd->add_option("--camera-path", args->cameraPath, "camera path file (time px py pz qx qy qz qw)");
    // A time without a path would be ignored: refused instead.
    cmd->add_option("--time", args->time, "time on the camera path, seconds")->needs(path);
    cmd->add_option("--out", args->out, "output image (.png sRGB 8-bit or .exr linear half)")->required();
    cmd->add_option("--heatmap", args->heatmap, "coplanarity heatmap image: per pixel the largest number of fragments in one depth layer, "
                   "in Fig. 13's colours (GPU detector); prints C_p");
    cmd->add_option("--highlight-coplanar", args->highlight,
                    "the image with coplanar and self-intersecting surfaces tinted by the heatmap's colours (Fig. 12)");
    addZoomOptions(cmd, args->zoom, false, "size (the heatmap is of the frame drawn)");
    addLodOptions(cmd, args->lod);
    cmd->add_option("--depth-tie-ulps", args->depthTieUlps,
                    "depths within this many float ulps (relative) are one layer (default: the scene's, 1024)")
        ->check(CLI::Range(0.0, 8388608.0));  // 2^23 ulps: depths within a factor of two
    addSettingsOptions(cmd, args->settings);
    cmd->callback([args] { run(*args); });
}

}  // namespace strata
