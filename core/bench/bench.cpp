#include "bench/bench.hpp"

#include "gl/debug.hpp"
#include "io/interrupt.hpp"
#include "oit/technique.hpp"
#include "frame/frame_renderer.hpp"
#include "frame/zoom_calibration.hpp"

#include <algorithm>
#include <chrono>
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

BudgetPin parseBudgetPin(const std::string& text, int ladderLevels) {
    const auto fail = [&] {
        return std::invalid_argument("budget pin '" + text + "': expected ZOOM,LEVEL with a zoom of 1..16 and a LOD ladder level of 0.." +
                                     std::to_string(ladderLevels - 1));
    };
    const std::size_t comma = text.find(',');
    if (comma == std::string::npos) throw fail();
    BudgetPin pin;
    try {
        std::size_t used = 0;
        pin.zoom = std::stoi(text.substr(0, comma), &used);
        if (used != comma) throw fail();
        pin.lodLevel = std::stoi(text.substr(comma + 1), &used);
        if (used != text.size() - comma - 1) throw fail();
    } catch (const std::logic_error&) {
        throw fail();
    }
    if (pin.zoom < 1 || pin.zoom > 16 || pin.lodLevel < 0 || pin.lodLevel >= ladderLevels) throw fail();
    return pin;
}

void checkBudgetPin(const BudgetPin& pin, const std::optional<ZoomBudget>& budget, BudgetLevers levers) {
    if (!budget) throw std::invalid_argument("bench: a pinned state needs a frame budget");
    if (pin.lodLevel > 0 && !levers.lod)
        throw std::invalid_argument("bench: a pinned LOD level above 0 needs the LOD lever (--lod auto, --budget-levers lod)");
    if (pin.zoom > 1 && !levers.zoom)
        throw std::invalid_argument("bench: a pinned zoom above 1 needs the zoom lever (--budget-levers zoom)");
    if (pin.zoom > budget->maxZoom)
        throw std::invalid_argument("bench: the pinned zoom " + std::to_string(pin.zoom) + " is above --zoom-max " +
                                    std::to_string(budget->maxZoom));
}

std::vector<BudgetExcursion> budgetExcursions(const std::vector<double>& ms, double targetMs, double band) {
    std::vector<BudgetExcursion> runs;
    const double limit = targetMs * (1.0 + band);
    for (std::size_t f = 0; f < ms.size(); ++f) {
        if (ms[f] <= limit) continue;
        if (runs.empty() || runs.back().firstFrame + runs.back().frames != int(f)) runs.push_back({int(f), 0, 0.0});
        runs.back().frames += 1;
        runs.back().peakOverTarget = std::max(runs.back().peakOverTarget, ms[f] / targetMs);
    }
    return runs;
}

std::vector<std::string> benchModeIds(const std::vector<std::string>& requested) {
    std::vector<std::string> modes = requested;
    if (modes.empty())
        for (const auto& e : techniqueRegistry()) modes.push_back(e.info.id);
    for (const auto& m : modes)
        if (!findTechnique(m)) createTechnique(m);  // throws the list of known ids
    // The references render first, so every technique is compared on the same frames: abuffer,
    // and abuffer-volume when a volumetric technique is benched (their model is not abuffer's).
    const bool volumetric = std::any_of(modes.begin(), modes.end(), [](const std::string& m) {
        return findTechnique(m)->info.family == "volumetric";
    });
    for (const char* reference : {"abuffer-volume", "abuffer"}) {
        if (std::string(reference) == "abuffer-volume" && !volumetric) continue;
        modes.erase(std::remove(modes.begin(), modes.end(), reference), modes.end());
        modes.insert(modes.begin(), reference);
    }
    return modes;
}

std::string benchReferenceOf(const std::string& id) {
    return findTechnique(id)->info.family == "volumetric" ? "abuffer-volume" : "abuffer";
}

BenchReport runBench(const GpuScene& scene, const BenchOptions& options) {
    if (options.frames < 1) throw std::invalid_argument("bench: --frames must be at least 1");
    const std::vector<std::string> modes = benchModeIds(options.modes);
    auto requested = [&](const std::string& id) {
        return options.modes.empty() || std::find(options.modes.begin(), options.modes.end(), id) != options.modes.end();
    };

    BenchReport report;
    report.scene = options.sceneName;
    report.size = options.size;
    report.frames = options.frames;
    report.device = gl::currentDeviceInfo();
    report.triangles = scene.triangleCount();
    report.textureBytes = scene.textureBytes();
    report.objects = scene.objects().size();
    report.meshes = scene.meshCount();
    report.meshTriangles = scene.meshTriangleCount();
    report.meshBytes = scene.meshBytes();
    report.zoom = options.budget ? 0 : options.zoom;
    report.zoomFilter = std::string(deflectFilterName(options.zoomFilter));
    report.budget = options.budget;
    // The LOD lever needs LOD previews (an auto LOD controller); without them the zoom steers alone.
    const BudgetLevers levers{options.levers.zoom || !options.lodPreview,
                              options.levers.lod && bool(options.lodPreview)};
    if (options.budget) {
        report.zoomController = options.budgetPin ? "pinned" : std::string(zoomControllerName(options.zoomController));
        report.budgetLevers = to_string(levers);
        report.budgetPin = options.budgetPin;
    }
    if (options.budgetPin) checkBudgetPin(*options.budgetPin, options.budget, levers);
    // A pinned run draws its state from the warm-up on: its first timed frame is not the first
    // at that zoom (the targets are sized before it).
    const double pinnedBoundPx =
        options.budgetPin && levers.lod ? options.lodLadder.bound(options.budgetPin->lodLevel) : 0.0;
    // A zoomed technique is compared with the reference at zoom 1: the reference's own rows then
    // render like any other technique's, against a reference technique of their own.
    // So is a technique drawn with stand-ins (BenchOptions::lod): the reference draws geometry.
    // So is every technique against a supersampled reference.
    if (options.referenceSupersample < 1 || options.referenceSupersample > 4)
        throw std::invalid_argument("bench: the reference's supersampling must be 1 to 4");
    const bool zoomed = options.zoom > 1 || options.budget.has_value() || bool(options.lod) ||
                        options.referenceSupersample > 1;
    report.referenceSupersample = options.referenceSupersample;
    report.lod = options.lodReport;

    std::vector<Camera> cameras = benchCameras(scene, options);
    {
        // Coplanarity at the bench's size from the GPU detector, on the first camera: C_p and the
        // R_h any one-fragment-per-layer peeling reaches (the detector's passes are not timed).
        FrameRenderer detector;
        FrameOptions detect;
        detect.timePasses = false;
        detect.detectCoplanarity = true;
        const FrameResult r = detector.render(scene, cameras.front(), options.size, nullptr, detect);
        report.coplanarityProbability = r.coplanarity->coplanarityProbability();
        report.coplanarityOnePerLayerRobustness = r.coplanarity->oneFragmentPerLayerRobustness();
        report.pixelsByLargestLayer = r.coplanarity->pixelsByLargestLayer;
        if (options.coplanarityHeatmap)
            options.coplanarityHeatmap(coplanarityHeatmap(detector.coplanarity()->readPixels().largestLayer,
                                                          r.renderSize.x, r.renderSize.y));
    }

    // Every frame is compared as soon as it is read back, against the reference frame for the same
    // camera, so no more than two frames per reference are held whatever the frame count. The
    // references render first; their technique objects are kept to render the reference frames
    // the other techniques need. Without a camera path every frame has the same camera and one
    // reference frame serves them all.
    struct Reference {
        std::unique_ptr<Technique> technique;
        Image image;
        int key = -1;  // the frame the image shows (0 for every frame of a fixed camera)
    };
    std::map<std::string, Reference> references;  // by id: abuffer, abuffer-volume
    // References draw in a renderer of their own, so a zoomed technique's targets keep their size.
    FrameRenderer renderer, referenceRenderer;
    auto keyOf = [&](int f) { return options.cameraPath ? f : 0; };
    auto referenceFor = [&](Reference& ref, const std::string& referenceId, int f) -> const Image& {
        if (ref.key != keyOf(f)) {
            if (!ref.technique) ref.technique = createConfiguredTechnique(referenceId, options.settings);
            FrameOptions untimed;
            untimed.timePasses = false;
            const int n = options.referenceSupersample;
            referenceRenderer.render(scene, cameras[f], options.size * n, ref.technique.get(), untimed);
            gl::checkGl("bench reference frame");
            ref.image = n > 1 ? averageDown(referenceRenderer.readOutput(), n) : referenceRenderer.readOutput();
            ref.key = keyOf(f);
            if (options.referenceFrame && referenceId == "abuffer") options.referenceFrame(f, ref.image);
        }
        return ref.image;
    };
    report.modesPlanned = 0;
    for (const auto& id : modes) report.modesPlanned += benchReferenceOf(id) != id || requested(id);  // rows, as below
    for (std::size_t m = 0; m < modes.size() && !report.interrupted; ++m) {
        const std::string& id = modes[m];
        const std::string referenceId = benchReferenceOf(id);
        // Zoomed, an unrequested reference needs no rows of its own (referenceFor draws its frames).
        if (zoomed && referenceId == id && !requested(id)) continue;
        if (interruptSignal()) {
            report.interrupted = true;
            break;
        }
        if (options.progress)
            options.progress("bench: [" + std::to_string(m + 1) + "/" + std::to_string(modes.size()) + "] " + id);
        std::unique_ptr<Technique> owned = createConfiguredTechnique(id, options.settings);
        Technique* technique = owned.get();
        const bool isReference = referenceId == id && !zoomed;
        Reference& reference = references[referenceId];
        if (isReference) reference.technique = std::move(owned);

        FrameOptions frameOptions;
        frameOptions.countFragments = true;
        frameOptions.zoom = options.budgetPin ? options.budgetPin->zoom : options.budget ? 1 : options.zoom;
        frameOptions.zoomFilter = options.zoomFilter;
        if (options.lod)
            frameOptions.standIns = options.lod(cameras.front(), options.size, options.warmupFrames, pinnedBoundPx).standIns;
        for (int w = 0; w < options.warmupFrames; ++w) renderer.render(scene, cameras.front(), options.size, technique, frameOptions);
        gl::checkGl(("bench warm-up of " + id).c_str());

        BenchMode mode;
        mode.id = id;
        mode.family = technique->info().family;
        mode.robust = technique->info().robust;
        mode.handlesCoplanarity = technique->info().handlesCoplanarity;
        mode.rgbTransmittance = technique->info().rgbTransmittance;
        mode.settingDescriptions = technique->settingDescriptions();
        mode.settings = technique->settings();
        std::unique_ptr<BudgetGovernor> controller;
        // Under a budget, each frame is also rendered as it would be without one (zoom 1, every
        // object as geometry) by a technique and renderer of its own, untimed: what the budget's
        // choices cost in image quality, frame by frame (BenchMode::framePsnr).
        std::unique_ptr<Technique> unconstrainedTechnique;
        FrameRenderer unconstrainedRenderer;
        if (options.budget) unconstrainedTechnique = createConfiguredTechnique(id, options.settings);
        if (options.budget && !options.budgetPin) {
            ZoomCostModel model;
            if (budgetNeedsCalibration(options.zoomController, levers))
                model = calibrateZoomCost(*technique, options.size, options.budget->maxZoom, options.progress).model;
            mode.calibratedModel = model;
            controller = std::make_unique<BudgetGovernor>(*options.budget, levers, options.zoomController, model);
        }
        mode.zoom = options.budget ? 0 : options.zoom;
        std::vector<double> gpu, cpu, threadCpu, drawCalls, opaque, frame, frameSpan, enlarge, lodMs, wall;
        std::map<std::string, std::vector<double>> perPass;
        std::vector<std::string> passOrder;
        ErrorAccumulator error;
        std::pair<Image, Image> first;  // the first frame and its reference
        for (int f = 0; f < options.frames; ++f) {
            // A signal ends the run between frames; this technique's rows are incomplete and dropped.
            if (interruptSignal()) {
                report.interrupted = true;
                break;
            }
            // The reference frame first (when it is not in hand), so the technique's frame is the
            // last one rendered when its output is read.
            if (!isReference) referenceFor(reference, referenceId, f);
            GovernorLoad load;
            double boundPx = pinnedBoundPx;  // 0: the LOD options' own
            if (controller) {
                const Camera& c = cameras[f];
                load.zoom.displaySize = options.size;
                load.zoom.transparentArea = transparentScreenArea(
                    scene, c.projection(float(options.size.x) / float(options.size.y)) * c.view(), options.size);
                if (levers.lod) load.lod = options.lodPreview(c, options.size, options.lodLadder.bounds());
                const GovernorChoice choice = controller->choose(load);
                frameOptions.zoom = choice.zoom;
                if (levers.lod && !load.lod.levels.empty()) boundPx = options.lodLadder.bound(choice.lodLevel);
            }  // a pinned run keeps the zoom and bound it warmed up with
            int frameImpostors = 0;
            if (options.lod) {
                const auto lodStart = std::chrono::steady_clock::now();
                const BenchLodFrame lod = options.lod(cameras[f], options.size, 1, boundPx);
                lodMs.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - lodStart).count());
                frameOptions.standIns = lod.standIns;
                frameImpostors = lod.impostorObjects;
                mode.impostorObjects = std::max(mode.impostorObjects, lod.impostorObjects);
                mode.impostorBytes = std::max(mode.impostorBytes, lod.impostorBytes);
            }
            FrameResult r = renderer.render(scene, cameras[f], options.size, technique, frameOptions);
            gl::checkGl(("bench frame of " + id).c_str());
            if (options.budget) {
                // A pinned state has no governor: no prediction, no loss of the rule's.
                const double predicted = controller ? controller->last().predictedMs : 0.0;
                mode.frameLodBoundPx.push_back(boundPx);
                mode.frameLossPx.push_back(controller ? controller->last().lossPx : 0.0);
                if (controller)
                    controller->observe(FrameCost{frameOptions.zoom, r.gpuMs, fragmentsRasterized(r.stats), load.zoom});
                mode.frameZoom.push_back(frameOptions.zoom);
                mode.frameMs.push_back(r.gpuMs);
                mode.framePredictedMs.push_back(std::isfinite(predicted) ? predicted : 0.0);
                mode.frameImpostorObjects.push_back(frameImpostors);
            }
            frame.push_back(r.gpuMs);
            frameSpan.push_back(r.gpuSpanMs);
            enlarge.push_back(r.enlargeMs);
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
            threadCpu.push_back(r.threadCpuMs);
            drawCalls.push_back(double(r.drawCalls));
            mode.passes = std::max(mode.passes, r.stats.passes);
            mode.bytes = std::max(mode.bytes, r.stats.bytes);
            mode.fragmentsTotal += r.fragmentsTotal.value_or(0);
            mode.fragmentsCaptured += r.stats.fragmentsCaptured;
            mode.overflowed = mode.overflowed || r.stats.overflowed;
            mode.regrows += r.stats.regrows;
            mode.tiles = std::max(mode.tiles, r.stats.tiles);
            mode.objectDraws += r.stats.objectDraws;
            mode.objectDrawsSkipped += r.stats.objectDrawsSkipped;
            mode.objectsCulled += r.objectsCulled;
            mode.unitsCulled += r.unitsCulled;
            mode.fragmentsTail += r.stats.fragmentsTail;
            mode.fragmentsDropped += r.stats.fragmentsDropped;
            mode.primitivesBounded += r.stats.primitivesBounded;

            Image image = renderer.readOutput();
            if (unconstrainedTechnique) {
                FrameOptions plain;
                plain.timePasses = false;
                unconstrainedRenderer.render(scene, cameras[f], options.size, unconstrainedTechnique.get(), plain);
                mode.framePsnr.push_back(compareImages(image, unconstrainedRenderer.readOutput()).psnr);
            }
            // Handed to firstFrame once the technique completed: a technique a signal stops
            // leaves no row and no image.
            if (f == 0 && options.firstFrame) first = {image, isReference ? image : reference.image};
            if (isReference) {
                // The reference against itself: zero by definition. Its frame is the one in hand.
                error.add(image, image);
                reference.image = std::move(image);
                reference.key = keyOf(f);
                if (options.referenceFrame && id == "abuffer") options.referenceFrame(f, reference.image);
            } else {
                error.add(image, reference.image);
            }
            if (options.wallFrames && !options.budget) {
                // The same frame again (its stand-ins too), as the peers time theirs: no pass
                // timers, no fragment count, wall clock to a glFinish (render ends with one).
                FrameOptions untimed = frameOptions;
                untimed.timePasses = false;
                untimed.countFragments = false;
                wall.push_back(renderer.render(scene, cameras[f], options.size, technique, untimed).cpuMs);
            }
        }
        if (report.interrupted) break;
        if (!wall.empty()) mode.wallMsMedian = percentile(wall, 0.5);
        if (options.firstFrame) options.firstFrame(id, first.first, first.second);
        // A fixed camera needs no more reference renders: free the reference's buffers now.
        if (isReference && !options.cameraPath) reference.technique.reset();
        mode.msMedian = percentile(gpu, 0.5);
        mode.msP95 = percentile(gpu, 0.95);
        mode.cpuMsMedian = percentile(cpu, 0.5);
        mode.threadCpuMsMedian = percentile(threadCpu, 0.5);
        mode.drawCallsMedian = percentile(drawCalls, 0.5);
        mode.lodMsMedian = lodMs.empty() ? 0.0 : percentile(lodMs, 0.5);
        mode.opaqueMsMedian = percentile(opaque, 0.5);
        mode.frameMsMedian = percentile(frame, 0.5);
        mode.frameSpanMsMedian = percentile(frameSpan, 0.5);
        mode.enlargeMsMedian = percentile(enlarge, 0.5);
        if (options.budget) {
            mode.budgetHits = budgetHits(mode.frameMs, options.budget->targetMs, options.budget->band);
            mode.excursions = budgetExcursions(mode.frameMs, options.budget->targetMs, options.budget->band);
        }
        for (const auto& name : passOrder) mode.passMsMedian.emplace_back(name, percentile(perPass[name], 0.5));
        mode.rmse = error.rmse();
        mode.psnr = error.psnr();
        mode.maxAbsError = error.maxAbsError();
        mode.robustnessRatio = mode.fragmentsTotal ? double(mode.fragmentsCaptured) / double(mode.fragmentsTotal) : 1.0;
        mode.reference = referenceId;
        if (referenceId != id || requested(id)) report.modes.push_back(std::move(mode));
    }
    return report;
}

}  // namespace strata
