#include "bench/bench.hpp"

#include "gl/debug.hpp"
#include "oit/technique.hpp"
#include "reference/raycast.hpp"
#include "frame/frame_renderer.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <stdexcept>

namespace strata {
namespace {

double percentile(std::vector<double> values, double p) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    double rank = p * double(values.size() - 1);
    std::size_t lo = std::size_t(std::floor(rank));
    std::size_t hi = std::min(lo + 1, values.size() - 1);
    return values[lo] + (values[hi] - values[lo]) * (rank - double(lo));
}

std::vector<Camera> benchCameras(const GpuScene& scene, const BenchOptions& options) {
    Camera base = defaultCamera(scene.scene(), scene.objects());
    std::vector<Camera> cameras;
    for (int i = 0; i < options.frames; ++i) {
        if (!options.cameraPath) {
            cameras.push_back(base);
            continue;
        }
        const CameraPath& path = *options.cameraPath;
        double t = path.startTime() + path.duration() * (options.frames > 1 ? double(i) / (options.frames - 1) : 0.0);
        Camera c = cameraAt(path, t, base);
        c.fitClipPlanes(scene.bounds());
        cameras.push_back(c);
    }
    return cameras;
}

}  // namespace

std::vector<std::string> benchModeIds(const std::vector<std::string>& requested) {
    std::vector<std::string> modes = requested;
    if (modes.empty())
        for (const auto& e : techniqueRegistry()) modes.push_back(e.info.id);
    for (const auto& m : modes)
        if (!findTechnique(m)) createTechnique(m);  // throws the list of known ids
    // The reference renders first, so every technique is compared on the same frames.
    modes.erase(std::remove(modes.begin(), modes.end(), "abuffer"), modes.end());
    modes.insert(modes.begin(), "abuffer");
    return modes;
}

BenchReport runBench(const GpuScene& scene, const BenchOptions& options) {
    if (options.frames < 1) throw std::invalid_argument("bench: --frames must be at least 1");
    const std::vector<std::string> modes = benchModeIds(options.modes);
    bool referenceRequested = std::find(options.modes.begin(), options.modes.end(), "abuffer") != options.modes.end() ||
                              options.modes.empty();

    BenchReport report;
    report.scene = options.sceneName;
    report.size = options.size;
    report.frames = options.frames;
    report.device = gl::currentDeviceInfo();
    report.triangles = scene.triangleCount();
    report.objects = scene.objects().size();

    std::vector<Camera> cameras = benchCameras(scene, options);
    {
        // Coplanarity: exact depth ties among transparent fragments, on the CPU at <= 128 px wide.
        int w = std::min(options.size.x, 128);
        int h = std::max(1, int(std::lround(double(w) * options.size.y / options.size.x)));
        ReferenceStats stats;
        RaycastReference(scene.scene(), scene.objects()).render(cameras.front(), w, h, &stats);
        report.coplanarityProbability = stats.coplanarityProbability();
    }

    // Every frame is compared as soon as it is read back, against the reference frame for the same
    // camera, so no more than two frames are held whatever the frame count. The reference renders
    // first; its technique object is kept to render the reference frames the other techniques need.
    // Without a camera path every frame has the same camera and one reference frame serves them all.
    FrameRenderer renderer;
    std::unique_ptr<Technique> reference;
    Image referenceImage;
    int referenceKey = -1;  // the frame the reference image shows (0 for every frame of a fixed camera)
    auto keyOf = [&](int f) { return options.cameraPath ? f : 0; };
    auto referenceFor = [&](int f) -> const Image& {
        if (referenceKey != keyOf(f)) {
            FrameOptions untimed;
            untimed.timePasses = false;
            renderer.render(scene, cameras[f], options.size, reference.get(), untimed);
            gl::checkGl("bench reference frame");
            referenceImage = renderer.readOutput();
            referenceKey = keyOf(f);
            if (options.referenceFrame) options.referenceFrame(f, referenceImage);
        }
        return referenceImage;
    };
    for (std::size_t m = 0; m < modes.size(); ++m) {
        const std::string& id = modes[m];
        if (options.progress)
            options.progress("bench: [" + std::to_string(m + 1) + "/" + std::to_string(modes.size()) + "] " + id);
        std::unique_ptr<Technique> owned = createConfiguredTechnique(id, options.settings);
        Technique* technique = owned.get();
        if (m == 0) reference = std::move(owned);

        FrameOptions frameOptions;
        frameOptions.countFragments = true;
        for (int w = 0; w < options.warmupFrames; ++w) renderer.render(scene, cameras.front(), options.size, technique, frameOptions);
        gl::checkGl(("bench warm-up of " + id).c_str());

        BenchMode mode;
        mode.id = id;
        mode.family = technique->info().family;
        mode.robust = technique->info().robust;
        mode.handlesCoplanarity = technique->info().handlesCoplanarity;
        mode.settingDescriptions = technique->settingDescriptions();
        mode.settings = technique->settings();
        std::vector<double> gpu, cpu, opaque;
        std::map<std::string, std::vector<double>> perPass;
        std::vector<std::string> passOrder;
        ErrorAccumulator error;
        for (int f = 0; f < options.frames; ++f) {
            // The reference frame first (when it is not in hand), so the technique's frame is the
            // last one rendered when its output is read.
            if (m > 0) referenceFor(f);
            FrameResult r = renderer.render(scene, cameras[f], options.size, technique, frameOptions);
            gl::checkGl(("bench frame of " + id).c_str());
            double techniqueMs = 0.0, opaqueMs = 0.0;
            std::map<std::string, double> frameByPass;
            for (const auto& p : r.passTimes) {
                (p.name == "opaque" ? opaqueMs : techniqueMs) += p.gpuMs;
                if (!frameByPass.count(p.name) && !perPass.count(p.name)) passOrder.push_back(p.name);
                frameByPass[p.name] += p.gpuMs;
            }
            for (const auto& [name, ms] : frameByPass) perPass[name].push_back(ms);
            gpu.push_back(techniqueMs);
            opaque.push_back(opaqueMs);
            cpu.push_back(r.cpuMs);
            mode.passes = std::max(mode.passes, r.stats.passes);
            mode.bytes = std::max(mode.bytes, r.stats.bytes);
            mode.fragmentsTotal += r.fragmentsTotal.value_or(0);
            mode.fragmentsCaptured += r.stats.fragmentsCaptured;
            mode.overflowed = mode.overflowed || r.stats.overflowed;
            mode.regrows += r.stats.regrows;
            mode.tiles = std::max(mode.tiles, r.stats.tiles);
            mode.objectDraws += r.stats.objectDraws;
            mode.objectDrawsSkipped += r.stats.objectDrawsSkipped;
            mode.fragmentsTail += r.stats.fragmentsTail;

            Image image = renderer.readOutput();
            if (m == 0) {
                // The reference against itself: zero by definition. Its frame is the one in hand.
                error.add(image, image);
                referenceImage = std::move(image);
                referenceKey = keyOf(f);
                if (options.referenceFrame) options.referenceFrame(f, referenceImage);
                if (f == 0 && options.firstFrame) options.firstFrame(id, referenceImage);
            } else {
                error.add(image, referenceImage);
                if (f == 0 && options.firstFrame) options.firstFrame(id, image);
            }
        }
        // A fixed camera needs no more reference renders: free the reference's buffers now.
        if (m == 0 && !options.cameraPath) reference.reset();
        mode.msMedian = percentile(gpu, 0.5);
        mode.msP95 = percentile(gpu, 0.95);
        mode.cpuMsMedian = percentile(cpu, 0.5);
        mode.opaqueMsMedian = percentile(opaque, 0.5);
        for (const auto& name : passOrder) mode.passMsMedian.emplace_back(name, percentile(perPass[name], 0.5));
        mode.rmse = error.rmse();
        mode.psnr = error.psnr();
        mode.maxAbsError = error.maxAbsError();
        mode.robustnessRatio = mode.fragmentsTotal ? double(mode.fragmentsCaptured) / double(mode.fragmentsTotal) : 1.0;
        if (m > 0 || referenceRequested) report.modes.push_back(std::move(mode));
    }
    return report;
}

}  // namespace strata
