// Immersive mode (see immersive.hpp), a mode of the window loop: trace-driven camera, two-step
// prediction, GPU deflection, live viewing error per predictor and deflection, optional
// side-by-side stereo. Its panel is viewer/immersive_panel.cpp.
#include "immersive.hpp"

#include <stdexcept>

#ifndef STRATA_HAVE_TRACKING

namespace strata {

WindowModeFactory immersiveMode(const ViewOptions&, Scene) {
    throw std::runtime_error("immersive mode needs the tracking library (Eigen3), which this build lacks");
}

}  // namespace strata

#else

#include "immersive_panel.hpp"
#include "lod_options.hpp"
#include "lod_panel.hpp"

#include "gl/context.hpp"
#include "render/deflection_warp.hpp"
#include "zoom_driver.hpp"
#include "frame/frame_renderer.hpp"
#include "tracking/deflection.hpp"
#include "tracking/predictor.hpp"
#include "tracking/trace_io.hpp"
#include "tracking/viewing_error.hpp"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace strata {
namespace {

constexpr std::array<tracking::Deflect, 3> kDeflects = {tracking::Deflect::None, tracking::Deflect::Shift,
                                                        tracking::Deflect::Homography};

// The truth beside a measured trace: "x-measured.path" -> "x-truth.path" when it exists.
std::filesystem::path truthBeside(const std::filesystem::path& measured) {
    std::string name = measured.filename().string();
    auto at = name.find("-measured");
    if (at == std::string::npos) return {};
    name.replace(at, 9, "-truth");
    std::filesystem::path truth = measured.parent_path() / name;
    return std::filesystem::exists(truth) ? truth : std::filesystem::path();
}

int indexOf(const std::vector<std::string>& names, const std::string& name, const char* what) {
    for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == name) return int(i);
    std::string known;
    for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
    throw std::runtime_error(std::string("view: unknown ") + what + " `" + name + "` (known: " + known + ")");
}

// Every predictor fed the same samples as they fall due; the selected one drives the view, the
// others are scored beside it so the panel compares them on the same head motion.
class HeadTracking {
public:
    explicit HeadTracking(tracking::Trace measured) : measured_(std::move(measured)) {
        for (const auto& name : tracking::predictorNames()) predictors_.push_back(tracking::makePredictor(name));
    }
    const tracking::PoseSample& firstSample() const { return measured_.front(); }
    double start() const { return measured_.front().t; }
    double end() const { return measured_.back().t; }
    std::size_t fed() const { return next_; }
    double latestSampleTime() const { return next_ ? measured_[next_ - 1].t : start(); }

    void restart() {
        for (auto& p : predictors_) p->reset();
        next_ = 0;
    }
    void feedUntil(double traceTime) {
        for (; next_ < measured_.size() && measured_[next_].t <= traceTime; ++next_)
            for (auto& p : predictors_) p->update(measured_[next_]);
    }
    // What predictor i has adapted to (empty when it adapts nothing).
    std::string stateOf(std::size_t i) const { return predictors_[i]->describeState(); }
    std::vector<tracking::PoseSample> predictAll(double time) const {
        std::vector<tracking::PoseSample> out;
        for (const auto& p : predictors_) out.push_back(p->predict(time));
        return out;
    }

private:
    tracking::Trace measured_;
    std::vector<std::unique_ptr<tracking::Predictor>> predictors_;
    std::size_t next_ = 0;
};

using tracking::toEigen;
using tracking::toGlm;

// tracking's pinhole for core's camera: fovY, square pixels, principal point at the centre.
tracking::Intrinsics intrinsicsFor(const Camera& camera, glm::ivec2 size) {
    return tracking::Intrinsics::fromFovY(size.x, size.y, camera.fovYDegrees);
}

struct Eye {
    FrameRenderer renderer;
    DeflectionWarp warp;
    Camera rendered;             // camera of the rendered image (pose 1)
    std::uint64_t uncovered = 0; // border pixels of the last deflection
    int zoom = 1;                // the rendered image is at 1/zoom of the eye's size
};

// Exponential moving average of a time in seconds; the first sample sets it.
struct Ema {
    double value = 0.0;
    bool seeded = false;
    void add(double x, double weight = 0.1) {
        value = seeded ? value + weight * (x - value) : x;
        seeded = true;
    }
};

class ImmersiveMode final : public WindowMode {
public:
    ImmersiveMode(const ViewOptions& options, Scene scene, tracking::Trace measured, tracking::Trace truth,
                  std::string truthLabel)
        : options_(options), scene_(std::move(scene)), tracking_(std::move(measured)), truth_(std::move(truth)),
          truthLabel_(std::move(truthLabel)) {
        device_ = gl::currentDeviceInfo();
        base_ = defaultCamera(scene_.scene(), scene_.objects());
        firstPosition_ = toGlm(tracking_.firstSample().p);
        technique_ = createConfiguredTechnique(options.mode, viewSettings(options, device_));
        predictorNames_ = tracking::predictorNames();
        for (auto d : kDeflects) deflectionNames_.emplace_back(tracking::deflectName(d));
        choices_.predictor = indexOf(predictorNames_, options.predictor, "predictor");
        choices_.deflection = int(tracking::parseDeflect(options.deflect));
        choices_.filter = int(DeflectFilter::Bilinear);
        choices_.stereo = options.stereo;
        zoom_.choices() = zoomChoicesFrom(options);
        lod_ = makeWindowLod(scene_, options.lod);  // as the walkthrough window's
        choices_.ipdMm = float(options.ipdMm);
        choices_.extraLatencyMs = float(options.extraLatencyMs);
        history_.resize(predictorNames_.size() * kDeflects.size());
    }

    void start(double now) override {
        origin_ = now;
        tracking_.restart();
    }

    void update(double now, double, const CallbackInput& input) override {
        for (int key : input.pressed)
            if (key == GLFW_KEY_SPACE && !ImGui::GetIO().WantCaptureKeyboard) requests_.togglePause = true;
        if (requests_.togglePause) togglePause(now);
        requests_ = {};
        inFlight_.t0 = now;
    }

    // Steps 1 and 2 (immersive.hpp): predict, render, re-read, predict again, deflect, present.
    void render(glm::ivec2 size, Presenter& presenter) override {
        const bool stereo = choices_.stereo;
        const int eyes = stereo ? 2 : 1;
        inFlight_.eyeSize = glm::ivec2(stereo ? std::max(size.x / 2, 1) : size.x, size.y);
        inFlight_.trace0 = traceTimeAtFrameStart(inFlight_.t0);
        inFlight_.paceScale = paused_ ? 0.0 : 1.0;  // a paused trace stands still in time
        // Step 1: predict for the expected display time and render there.
        tracking_.feedUntil(inFlight_.trace0);
        const double display1 = inFlight_.trace0 + inFlight_.paceScale * startToDisplay_.value + extraLatency();
        inFlight_.first = tracking_.predictAll(display1);
        lastHorizon1_ = display1 - tracking_.latestSampleTime();
        const float signs[2] = {stereo ? -1.0f : 0.0f, 1.0f};
        const std::size_t predictor = std::size_t(choices_.predictor);
        // Section 4.2 of zoom rendering: the head's angular speed between the last two frames'
        // predicted poses raises the zoom during fast turns. One zoom for both eyes.
        headDegPerSecond_ = headSpeed(inFlight_.first[predictor], inFlight_.trace0);
        FrameOptions frameOptions;
        frameOptions.timePasses = true;
        frameOptions.enlarge = false;  // the deflection enlarges, in the same pass
        // One selection for both eyes, from between them (their views differ by the eye distance,
        // far below what moves an object's impostor choice), with the bound the budget sets. A
        // failed bake is reported like a failed frame, and the eyes draw geometry.
        bool zoomBegun = false;  // a failed begin leaves no choice for end to learn from
        try {
            zoom_.begin(scene_, eyeCamera(inFlight_.first[predictor], 0.0f), inFlight_.eyeSize, technique_.get(),
                        frameOptions, headDegPerSecond_, lod_.get());
            zoomBegun = true;
            frameOptions.standIns = lod_->select(eyeCamera(inFlight_.first[predictor], 0.0f), inFlight_.eyeSize);
        } catch (const std::exception& e) {
            if (smokeTest()) throw;
            lastError_ = e.what();
            frameOptions.standIns = nullptr;
        }
        for (int e = 0; e < eyes; ++e) {
            eyes_[e].rendered = eyeCamera(inFlight_.first[predictor], signs[e]);
            renderEye(eyes_[e], inFlight_.eyeSize, frameOptions);
        }
        if (zoomBegun) zoom_.end(frame_, technique_.get());
        // Step 2: re-read, predict again for the now better-known display time, deflect.
        inFlight_.t1 = glfwGetTime();
        const double trace1 = inFlight_.trace0 + inFlight_.paceScale * (inFlight_.t1 - inFlight_.t0);
        tracking_.feedUntil(trace1);
        const double display2 = trace1 + inFlight_.paceScale * rereadToDisplay_.value + extraLatency();
        inFlight_.second = tracking_.predictAll(display2);
        const tracking::Deflect deflect = kDeflects[std::size_t(choices_.deflection)];
        std::array<PresentRegion, 2> regions;
        for (int e = 0; e < eyes; ++e) {
            deflectEye(eyes_[e], inFlight_.eyeSize, inFlight_.second[predictor], deflect);
            regions[e] = {eyes_[e].warp.outputColor(), {e * inFlight_.eyeSize.x, 0}, inFlight_.eyeSize};
        }
        presenter.present(size, std::span(regions.data(), std::size_t(eyes)));
    }

    // Step 3: the swap has returned; take now as the display time and score every combination.
    void afterSwap() override {
        const double t2 = glfwGetTime();
        if (!paused_) {
            startToDisplay_.add(t2 - inFlight_.t0);
            rereadToDisplay_.add(t2 - inFlight_.t1);
        }
        score(inFlight_.trace0 + inFlight_.paceScale * (t2 - inFlight_.t0) + extraLatency());
    }

    void drawPanel(glm::ivec2 size, const std::string& lastGlError) override {
        ImmersivePanelState state;
        state.windowSize = size;
        state.eyeSize = inFlight_.eyeSize;
        state.zoom = &zoom_;
        state.lod = lod_.get();
        state.headDegPerSecond = headDegPerSecond_;
        state.sceneName = scene_.scene().name;
        state.techniqueId = technique_->info().id;
        state.renderer = device_.renderer;
        state.traceName = options_.trace->filename().string();
        state.truthLabel = truthLabel_;
        state.traceTime = tracking_.latestSampleTime() - tracking_.start();
        state.traceDuration = tracking_.end() - tracking_.start();
        state.samplesFed = tracking_.fed();
        state.loops = loops_;
        state.paused = paused_;
        state.predictors = predictorNames_;
        state.predictorState = tracking_.stateOf(std::size_t(choices_.predictor));
        state.deflections = deflectionNames_;
        state.horizon1 = lastHorizon1_;
        state.startToDisplay = startToDisplay_.value;
        state.rereadToDisplay = rereadToDisplay_.value;
        state.deflectionDeg = lastDeflectDeg_;
        state.uncoveredPixels = eyes_[0].uncovered;
        if (kDeflects[std::size_t(choices_.deflection)] == tracking::Deflect::Shift) state.shift = lastShift_;
        state.errorDeg = lastErrorDeg_;
        state.errorMm = lastErrorMm_;
        state.errorHistory = &history_;
        state.frame = &frame_;
        state.lastGlError = lastGlError;
        state.lastError = lastError_;
        drawImmersivePanel(state, choices_, requests_);
    }

    void reportLastFrame() override {
        const FrameHistory& h = historyOf(choices_.predictor, choices_.deflection);
        std::printf("immersive: %s + %s, %llu frames scored, mean error %.3f deg, start-to-display %.1f ms\n",
                    predictorNames_[std::size_t(choices_.predictor)].c_str(),
                    deflectionNames_[std::size_t(choices_.deflection)].c_str(),
                    static_cast<unsigned long long>(scored_), h.mean(), startToDisplay_.value * 1e3);
        zoom_.printFigures();
        printLodFigures(*lod_);
    }

private:
    // What steps 1 and 2 leave for step 3, after the swap.
    struct FrameInFlight {
        double t0 = 0.0, t1 = 0.0;    // wall clock at frame start and at the re-read
        double trace0 = 0.0;          // trace time at frame start
        double paceScale = 1.0;       // 0 while paused
        glm::ivec2 eyeSize{0};
        std::vector<tracking::PoseSample> first, second;  // every predictor's step-1 and step-2 pose
    };

    bool smokeTest() const { return options_.exitAfterFrames > 0; }
    double extraLatency() const { return double(choices_.extraLatencyMs) * 1e-3; }

    void togglePause(double now) {
        if (paused_) origin_ += now - pausedAt_;
        else pausedAt_ = now;
        paused_ = !paused_;
    }

    // Trace time at wall time `now`; wraps (and restarts the predictors) only at frame start so
    // one frame's three readings share a time base.
    double traceTimeAtFrameStart(double now) {
        double wall = (paused_ ? pausedAt_ : now) - origin_;
        double duration = tracking_.end() - tracking_.start();
        if (duration > 0.0 && wall > duration) {
            double loops = std::floor(wall / duration);
            origin_ += loops * duration;
            wall -= loops * duration;
            tracking_.restart();
            ++loops_;
        }
        return tracking_.start() + wall;
    }

    Camera eyeCamera(const tracking::PoseSample& head, float eyeSign) const {
        Camera c = base_;
        c.orientation = glm::normalize(base_.orientation * toGlm(head.q));
        glm::vec3 headPosition = base_.position + base_.orientation * (toGlm(head.p) - firstPosition_);
        c.position = headPosition + c.orientation * glm::vec3(eyeSign * 0.5f * choices_.ipdMm * 1e-3f, 0.0f, 0.0f);
        c.fitClipPlanes(scene_.bounds());
        return c;
    }

    // Degrees per second between the previous frame's predicted head orientation and this one's,
    // over the trace time that passed between the two frames' starts. Not over the difference of
    // their predicted display times: that also moves with the latency estimate, which falls fast
    // after a slow frame (the first one calibrates level of detail, ~250 ms on llvmpipe). Divided
    // by it, the head-speed floor raised a fixed zoom of 2 to 3 or 4 in 2 of 4 smoke runs; divided
    // by the trace time, in none of 4.
    double headSpeed(const tracking::PoseSample& head, double traceTime) {
        double speed = 0.0;
        if (hasLastHead_ && traceTime > lastHeadTime_)
            speed = tracking::radToDeg(tracking::angleBetween(lastHead_.q, head.q)) / (traceTime - lastHeadTime_);
        lastHead_ = head;
        lastHeadTime_ = traceTime;
        hasLastHead_ = true;
        return speed;
    }

    void renderEye(Eye& eye, glm::ivec2 eyeSize, const FrameOptions& frameOptions) {
        // Set first: the targets take the new size even when the technique then fails, and the
        // deflection must read them at the zoom they were sized for.
        eye.zoom = frameOptions.zoom;
        try {
            frame_ = eye.renderer.render(scene_, eye.rendered, eyeSize, technique_.get(), frameOptions);
        } catch (const std::exception& e) {
            if (smokeTest()) throw;
            lastError_ = e.what();
        }
    }

    void deflectEye(Eye& eye, glm::ivec2 eyeSize, const tracking::PoseSample& latest, tracking::Deflect deflect) {
        const tracking::Intrinsics k = intrinsicsFor(eye.rendered, eyeSize);
        const glm::quat latestOrientation = glm::normalize(base_.orientation * toGlm(latest.q));
        const Eigen::Quaterniond r1 = toEigen(eye.rendered.orientation), r2 = toEigen(latestOrientation);
        DeflectionParams params;
        params.filter = DeflectFilter(choices_.filter);
        params.countOutside = true;
        params.zoom = eye.zoom;  // the enlargement folds into the deflection (render/deflection_warp.hpp)
        params.mode = DeflectMode::Shift;  // zero shift with nearest: an exact copy for `none`
        if (deflect == tracking::Deflect::None) {
            params.filter = DeflectFilter::Nearest;
        } else if (deflect == tracking::Deflect::Shift) {
            const Eigen::Vector2d s = tracking::deflectionShift(k, r1, r2);
            params.shift = shiftFromYDown({s.x(), s.y()});
        } else {
            params.mode = DeflectMode::Homography;
            params.homography = homographyFromYDownForward(toGlm(tracking::deflectionHomography(k, r1, r2)), k.height);
        }
        eye.warp.apply(eye.renderer.targets().outputColor(), eyeSize, params);
        eye.uncovered = eye.warp.outsidePixels();
        lastShift_ = params.shift;
        lastDeflectDeg_ = tracking::radToDeg(tracking::angleBetween(r1, r2));
    }

    void score(double displayTime) {
        // Past the trace's end the truth is clamped: nothing honest to score.
        if (displayTime > tracking_.end()) return;
        const tracking::PoseSample truth = tracking::sampleAt(truth_, displayTime);
        const tracking::Intrinsics k = intrinsicsFor(base_, inFlight_.eyeSize);
        for (std::size_t p = 0; p < inFlight_.first.size(); ++p)
            for (std::size_t d = 0; d < kDeflects.size(); ++d) {
                const auto err = tracking::viewingError(kDeflects[d], k, inFlight_.first[p], inFlight_.second[p], truth);
                history_[p * kDeflects.size() + d].push(float(err.angleDeg));
                if (int(p) == choices_.predictor && int(d) == choices_.deflection) {
                    lastErrorDeg_ = err.angleDeg;
                    lastErrorMm_ = err.positionMm;
                }
            }
        ++scored_;
    }

    const FrameHistory& historyOf(int predictor, int deflection) const {
        return history_[std::size_t(predictor) * kDeflects.size() + std::size_t(deflection)];
    }

    const ViewOptions& options_;
    gl::DeviceInfo device_;
    GpuScene scene_;
    HeadTracking tracking_;
    tracking::Trace truth_;
    std::string truthLabel_;
    Camera base_;
    glm::vec3 firstPosition_{0.0f};
    std::unique_ptr<Technique> technique_;
    std::array<Eye, 2> eyes_;
    FrameResult frame_;
    std::vector<std::string> predictorNames_, deflectionNames_;
    ImmersiveChoices choices_;
    ImmersiveRequests requests_;
    // Clock and timing.
    double origin_ = 0.0, pausedAt_ = 0.0;
    bool paused_ = false;
    std::uint64_t loops_ = 0, scored_ = 0;
    Ema startToDisplay_, rereadToDisplay_;
    double lastHorizon1_ = 0.0;
    FrameInFlight inFlight_;
    // Last deflection and errors.
    glm::vec2 lastShift_{0.0f};
    // Zoom rendering and the head speed that drives it; level of detail.
    ZoomDriver zoom_;
    std::unique_ptr<lod::LodController> lod_;
    tracking::PoseSample lastHead_;
    double lastHeadTime_ = 0.0, headDegPerSecond_ = 0.0;
    bool hasLastHead_ = false;
    double lastDeflectDeg_ = 0.0, lastErrorDeg_ = 0.0, lastErrorMm_ = 0.0;
    std::vector<FrameHistory> history_;  // predictor x deflection, degrees
    std::string lastError_;
};

}  // namespace

WindowModeFactory immersiveMode(const ViewOptions& options, Scene scene) {
    if (!options.trace) throw std::runtime_error("view: --immersive needs --trace FILE (a head-pose trace)");
    tracking::Trace measured = tracking::readTrace(options.trace->string());  // TraceError: file:line
    if (measured.empty()) throw std::runtime_error("view: trace " + options.trace->string() + " has no samples");
    tracking::Trace truth = measured;
    std::string truthLabel = "the measured trace (interpolated): the error shows prediction only";
    if (auto beside = truthBeside(*options.trace); !beside.empty()) {
        truth = tracking::readTrace(beside.string());
        truthLabel = beside.filename().string();
    }
    indexOf(tracking::predictorNames(), options.predictor, "predictor");  // fail before a window opens
    tracking::parseDeflect(options.deflect);
    if (!(options.ipdMm >= 0.0 && options.ipdMm <= 200.0)) throw std::runtime_error("view: --ipd must be 0..200 mm");
    if (!(options.extraLatencyMs >= 0.0 && options.extraLatencyMs <= 1000.0))
        throw std::runtime_error("view: --extra-latency must be 0..1000 ms");
    std::printf("immersive: trace %s (%zu samples, %.2f s), truth %s\n", options.trace->string().c_str(),
                measured.size(), measured.back().t - measured.front().t, truthLabel.c_str());
    return [&options, scene = std::move(scene), measured = std::move(measured), truth = std::move(truth),
            truthLabel](GLFWwindow*) mutable {
        return std::make_unique<ImmersiveMode>(options, std::move(scene), std::move(measured), std::move(truth),
                                               truthLabel);
    };
}

}  // namespace strata

#endif  // STRATA_HAVE_TRACKING
