// `strata render`: one frame of a scene with one technique, headless, to PNG or EXR.
#include "commands.hpp"
#include "open_scene.hpp"

#include "camera/camera_path.hpp"
#include "gl/context.hpp"
#include "gl/debug.hpp"
#include "io/atomic_file.hpp"
#include "oit/technique.hpp"
#include "oit/technique_settings.hpp"
#include "reference/raycast.hpp"
#include "render/frame_size.hpp"
#include "frame/frame_renderer.hpp"
#include "settings_options.hpp"

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
    SettingsArgs settings;
};

// Exact depth ties per pixel from the CPU ray cast, as a heat colour over a dimmed image:
// black none, then yellow (2 coplanar surfaces) to red (4 or more).
Image coplanarityHeatmap(const GpuScene& scene, const Camera& camera, const Image& frame) {
    RaycastReference reference(scene.scene(), scene.objects());
    Image heat(frame.width, frame.height);
    for (int y = 0; y < frame.height; ++y)
        for (int x = 0; x < frame.width; ++x) {
            int ties = reference.samplePixel(camera, frame.width, frame.height, x, y).depthTies;
            glm::vec3 base = glm::vec3(frame.at(x, y)) * 0.25f;
            glm::vec3 c = ties == 0 ? base : glm::mix(glm::vec3(1, 0.9f, 0.1f), glm::vec3(1, 0.05f, 0.02f),
                                                      glm::clamp(float(ties - 1) / 2.0f, 0.0f, 1.0f));
            heat.set(x, y, glm::vec4(c, 1.0f));
        }
    return heat;
}

void run(const RenderArgs& a) {
    glm::ivec2 size = parseSize(a.size);
    if (!findTechnique(a.mode)) createTechnique(a.mode);  // throws the list of known ids
    const SettingsById settings = resolveSettingsArgs({a.mode}, a.settings);
    // Images are written after the frame: refuse an unwritable destination before rendering.
    checkImageWritable(a.out);
    if (!a.heatmap.empty()) checkImageWritable(a.heatmap);
    Scene scene = openSceneAndWarn(a.scene);
    gl::HeadlessContext context;
    checkFrameSize(size);  // before the scene is uploaded or a target allocated
    GpuScene gpu(std::move(scene));
    auto technique = createConfiguredTechnique(a.mode, settings);
    Camera camera = defaultCamera(gpu.scene(), gpu.objects());
    if (!a.cameraPath.empty()) {
        camera = cameraAt(CameraPath::read(a.cameraPath), a.time, camera);
        camera.fitClipPlanes(gpu.bounds());
    }
    FrameRenderer renderer;
    FrameOptions options;
    options.countFragments = true;
    FrameResult result = renderer.render(gpu, camera, size, technique.get(), options);
    gl::checkGl("render");
    Image image = renderer.readOutput();
    gl::checkGl("read back");
    // The image and its heatmap appear together or not at all.
    OutputBatch outputs;
    writeImage(outputs, a.out, image);
    if (!a.heatmap.empty()) writeImage(outputs, a.heatmap, coplanarityHeatmap(gpu, camera, image));
    outputs.commit();
    const auto& s = result.stats;
    std::printf("%s: %s %dx%d, %.3f ms GPU (%d passes), %llu of %llu fragments%s\n", a.out.c_str(), a.mode.c_str(),
                size.x, size.y, result.gpuMs, s.passes, (unsigned long long)s.fragmentsCaptured,
                (unsigned long long)result.fragmentsTotal.value_or(0), s.overflowed ? ", OVERFLOWED" : "");
    for (const auto& p : result.passTimes)
        std::printf("  %-18s %9.3f ms GPU %9.3f ms CPU\n", p.name.c_str(), p.gpuMs, p.cpuMs);
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
    cmd->add_option("--heatmap", args->heatmap, "coplanarity heatmap image (exact depth ties per pixel, CPU ray cast)");
    addSettingsOptions(cmd, args->settings);
    cmd->callback([args] { run(*args); });
}

}  // namespace strata
