// Immersive mode (see immersive.hpp): trace-driven camera, two-step prediction, GPU deflection,
// live viewing error per predictor and deflection, optional side-by-side stereo.
#include "immersive.hpp"

#include <stdexcept>

#ifndef STRATA_HAVE_TRACKING

namespace strata {

int runImmersive(const ViewOptions&, Scene) {
    throw std::runtime_error("immersive mode needs the tracking library (Eigen3), which this build lacks");
}

}  // namespace strata

#else

#include "panel.hpp"
#include "presenter.hpp"
#include "window_capture.hpp"
#include "window_session.hpp"

#include "gl/debug.hpp"
#include "gl/shader_program.hpp"
#include "render/deflection_warp.hpp"
#include "render/frame_renderer.hpp"
#include "tracking/deflection.hpp"
#include "tracking/predictor.hpp"
#include "tracking/trace_io.hpp"
#include "tracking/viewing_error.hpp"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

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

void helpTip(const char* text) {
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text);
}

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

class Immersive {
public:
    Immersive(const ViewOptions& options, Scene scene, tracking::Trace measured, tracking::Trace truth,
              std::string truthLabel, GLFWwindow* window)
        : options_(options), window_(window), scene_(std::move(scene)), tracking_(std::move(measured)),
          truth_(std::move(truth)), truthLabel_(std::move(truthLabel)) {
        device_ = gl::currentDeviceInfo();
        base_ = defaultCamera(scene_.scene(), scene_.objects());
        technique_ = createConfiguredTechnique(options.mode, options.settings);
        predictor_ = indexOf(tracking::predictorNames(), options.predictor, "predictor");
        deflect_ = int(tracking::parseDeflect(options.deflect));
        stereo_ = options.stereo;
        ipdMm_ = float(options.ipdMm);
        extraLatencyMs_ = float(options.extraLatencyMs);
        history_.resize(tracking::predictorNames().size() * kDeflects.size());
    }

    void setFirstPosition(const glm::vec3& p) { firstPosition_ = p; }

    int run() {
        origin_ = glfwGetTime();
        tracking_.restart();
        while (!glfwWindowShouldClose(window_)) {
            glfwPollEvents();
            handleKeys();
            glm::ivec2 size;
            glfwGetFramebufferSize(window_, &size.x, &size.y);
            if (size.x <= 0 || size.y <= 0) {
                glfwWaitEvents();
                continue;
            }
            if (frame(size)) break;
        }
        return 0;
    }

private:
    bool smokeTest() const { return options_.exitAfterFrames > 0; }
    double extraLatency() const { return double(extraLatencyMs_) * 1e-3; }

    void handleKeys() {
        for (int key : callbackInput().pressed)
            if (key == GLFW_KEY_SPACE && !ImGui::GetIO().WantCaptureKeyboard) togglePause();
        callbackInput().pressed.clear();
        callbackInput().scroll = 0.0f;
    }

    void togglePause() {
        double now = glfwGetTime();
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
        c.orientation = glm::normalize(base_.orientation * tracking::toGlm(head.q));
        glm::vec3 headPosition = base_.position + base_.orientation * (tracking::toGlm(head.p) - firstPosition_);
        c.position = headPosition + c.orientation * glm::vec3(eyeSign * 0.5f * ipdMm_ * 1e-3f, 0.0f, 0.0f);
        c.fitClipPlanes(scene_.bounds());
        return c;
    }

    // One displayed frame; true when the smoke test is done.
    bool frame(glm::ivec2 size) {
        const int eyes = stereo_ ? 2 : 1;
        const glm::ivec2 eyeSize(stereo_ ? std::max(size.x / 2, 1) : size.x, size.y);
        const double t0 = glfwGetTime();
        const double trace0 = traceTimeAtFrameStart(t0);
        const double paceScale = paused_ ? 0.0 : 1.0;  // a paused trace stands still in time
        // Step 1: predict for the expected display time and render there.
        tracking_.feedUntil(trace0);
        const double display1 = trace0 + paceScale * startToDisplay_.value + extraLatency();
        const auto first = tracking_.predictAll(display1);
        lastHorizon1_ = display1 - tracking_.latestSampleTime();
        const float signs[2] = {stereo_ ? -1.0f : 0.0f, 1.0f};
        for (int e = 0; e < eyes; ++e) {
            eyes_[e].rendered = eyeCamera(first[std::size_t(predictor_)], signs[e]);
            renderEye(eyes_[e], eyeSize);
        }
        // Step 2: re-read, predict again for the now better-known display time, deflect.
        const double t1 = glfwGetTime();
        const double trace1 = trace0 + paceScale * (t1 - t0);
        tracking_.feedUntil(trace1);
        const double display2 = trace1 + paceScale * rereadToDisplay_.value + extraLatency();
        const auto second = tracking_.predictAll(display2);
        const tracking::Deflect deflect = kDeflects[std::size_t(deflect_)];
        for (int e = 0; e < eyes; ++e) deflectEye(eyes_[e], eyeSize, second[std::size_t(predictor_)], deflect);
        present(size, eyeSize, eyes);

        ++frameIndex_;
        bool finalFrame = smokeTest() && frameIndex_ >= std::uint64_t(options_.exitAfterFrames);
        WindowPixels scenePixels;
        if (finalFrame && options_.screenshot) scenePixels = readWindow(size);
        drawImGui(size, eyeSize);
        checkErrors();
        if (finalFrame) {
            if (options_.screenshot) saveWindow(*options_.screenshot, scenePixels, size);
            return true;
        }
        glfwSwapBuffers(window_);
        // Step 3: the swap has returned; take now as the display time and score every combination.
        const double t2 = glfwGetTime();
        if (!paused_) {
            startToDisplay_.add(t2 - t0);
            rereadToDisplay_.add(t2 - t1);
        }
        score(first, second, trace0 + paceScale * (t2 - t0) + extraLatency(), eyeSize);
        return false;
    }

    void renderEye(Eye& eye, glm::ivec2 eyeSize) {
        FrameOptions frameOptions;
        frameOptions.timePasses = true;
        frameOptions.countFragments = false;
        try {
            frame_ = eye.renderer.render(scene_, eye.rendered, eyeSize, technique_.get(), frameOptions);
        } catch (const std::exception& e) {
            if (smokeTest()) throw;
            lastError_ = e.what();
        }
    }

    void deflectEye(Eye& eye, glm::ivec2 eyeSize, const tracking::PoseSample& latest, tracking::Deflect deflect) {
        const tracking::Intrinsics k = intrinsicsFor(eye.rendered, eyeSize);
        const glm::quat latestOrientation = glm::normalize(base_.orientation * tracking::toGlm(latest.q));
        const Eigen::Quaterniond r1 = toEigen(eye.rendered.orientation), r2 = toEigen(latestOrientation);
        DeflectionParams params;
        params.filter = DeflectFilter(filter_);
        params.countOutside = true;
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

    void present(glm::ivec2 size, glm::ivec2 eyeSize, int eyes) {
        std::array<PresentRegion, 2> regions;
        for (int e = 0; e < eyes; ++e) regions[e] = {eyes_[e].warp.outputColor(), {e * eyeSize.x, 0}, eyeSize};
        presenter_.present(size, std::span(regions.data(), std::size_t(eyes)));
    }

    void score(const std::vector<tracking::PoseSample>& first, const std::vector<tracking::PoseSample>& second,
               double displayTime, glm::ivec2 eyeSize) {
        // Past the trace's end the truth is clamped: nothing honest to score.
        if (displayTime > tracking_.end()) return;
        const tracking::PoseSample truth = tracking::sampleAt(truth_, displayTime);
        const tracking::Intrinsics k = intrinsicsFor(base_, eyeSize);
        for (std::size_t p = 0; p < first.size(); ++p)
            for (std::size_t d = 0; d < kDeflects.size(); ++d) {
                const auto err = tracking::viewingError(kDeflects[d], k, first[p], second[p], truth);
                history_[p * kDeflects.size() + d].push(float(err.angleDeg));
                if (int(p) == predictor_ && int(d) == deflect_) {
                    lastErrorDeg_ = err.angleDeg;
                    lastErrorMm_ = err.positionMm;
                }
            }
        ++scored_;
    }

    void checkErrors() {
        auto errors = gl::takeErrors();
        if (errors.empty()) return;
        if (smokeTest()) throw std::runtime_error("view --immersive: GL error: " + errors.front());
        lastGlError_ = errors.back();
    }

    const FrameHistory& historyOf(int predictor, int deflect) const {
        return history_[std::size_t(predictor) * kDeflects.size() + std::size_t(deflect)];
    }

    void drawImGui(glm::ivec2 size, glm::ivec2 eyeSize) {
        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
        drawPanelWindow(size, eyeSize);
        ImGui::Render();
        glViewport(0, 0, size.x, size.y);
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    }

    void drawPanelWindow(glm::ivec2 size, glm::ivec2 eyeSize);

    void saveWindow(const std::filesystem::path& path, const WindowPixels& scene, glm::ivec2 size) {
        WindowPixels window = readWindow(size);
        writeWindowPng(path, window);
        std::printf("screenshot: %s %dx%d distinct_colors=%zu scene_colors=%zu panel_pixels=%zu\n",
                    path.string().c_str(), window.width, window.height, distinctColors(window),
                    distinctColors(scene), changedPixels(scene, window));
        const FrameHistory& h = historyOf(predictor_, deflect_);
        std::printf("immersive: %s + %s, %llu frames scored, mean error %.3f deg, start-to-display %.1f ms\n",
                    tracking::predictorNames()[std::size_t(predictor_)].c_str(),
                    std::string(tracking::deflectName(kDeflects[std::size_t(deflect_)])).c_str(),
                    static_cast<unsigned long long>(scored_), h.mean(), startToDisplay_.value * 1e3);
    }

    const ViewOptions& options_;
    GLFWwindow* window_;
    gl::DeviceInfo device_;
    GpuScene scene_;
    HeadTracking tracking_;
    tracking::Trace truth_;
    std::string truthLabel_;
    Camera base_;
    glm::vec3 firstPosition_{0.0f};
    std::unique_ptr<Technique> technique_;
    Presenter presenter_;
    std::array<Eye, 2> eyes_;
    FrameResult frame_;
    // Choices (the panel edits them).
    int predictor_ = 0, deflect_ = 2, filter_ = int(DeflectFilter::Bilinear);
    bool stereo_ = false;
    float ipdMm_ = 64.0f, extraLatencyMs_ = 0.0f;
    // Clock and timing.
    double origin_ = 0.0, pausedAt_ = 0.0;
    bool paused_ = false;
    std::uint64_t loops_ = 0, frameIndex_ = 0, scored_ = 0;
    Ema startToDisplay_, rereadToDisplay_;
    double lastHorizon1_ = 0.0;
    // Last deflection and errors.
    glm::vec2 lastShift_{0.0f};
    double lastDeflectDeg_ = 0.0, lastErrorDeg_ = 0.0, lastErrorMm_ = 0.0;
    std::vector<FrameHistory> history_;  // predictor x deflection, degrees
    std::string lastError_, lastGlError_;
};

void Immersive::drawPanelWindow(glm::ivec2 size, glm::ivec2 eyeSize) {
    const auto& names = tracking::predictorNames();
    ImGui::SetNextWindowPos(ImVec2(8.0f, 8.0f), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(400.0f, std::max(float(size.y) - 16.0f, 200.0f)), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(0.85f);
    ImGui::Begin("Strata - immersive");
    ImGui::TextWrapped("%s   %s", scene_.scene().name.c_str(), technique_->info().id.c_str());
    ImGui::TextWrapped("%s", device_.renderer.c_str());
    if (ImGui::CollapsingHeader("Head tracking", ImGuiTreeNodeFlags_DefaultOpen)) {
        ImGui::TextWrapped("trace %s", options_.trace->filename().string().c_str());
        ImGui::TextWrapped("truth: %s", truthLabel_.c_str());
        ImGui::Text("t %.2f / %.2f s   samples fed %zu   loop %llu", tracking_.latestSampleTime() - tracking_.start(),
                    tracking_.end() - tracking_.start(), tracking_.fed(), static_cast<unsigned long long>(loops_));
        if (ImGui::SmallButton(paused_ ? "resume (Space)" : "pause (Space)")) togglePause();
        ImGui::SetNextItemWidth(160.0f);
        if (ImGui::BeginCombo("predictor", names[std::size_t(predictor_)].c_str())) {
            for (std::size_t i = 0; i < names.size(); ++i)
                if (ImGui::Selectable(names[i].c_str(), int(i) == predictor_)) predictor_ = int(i);
            ImGui::EndCombo();
        }
        ImGui::SetNextItemWidth(160.0f);
        if (ImGui::BeginCombo("deflection", std::string(tracking::deflectName(kDeflects[std::size_t(deflect_)])).c_str())) {
            for (std::size_t i = 0; i < kDeflects.size(); ++i)
                if (ImGui::Selectable(std::string(tracking::deflectName(kDeflects[i])).c_str(), int(i) == deflect_))
                    deflect_ = int(i);
            ImGui::EndCombo();
        }
        const char* filters[] = {"nearest", "bilinear"};
        ImGui::SetNextItemWidth(160.0f);
        ImGui::Combo("warp sampling", &filter_, filters, 2);
        ImGui::SetNextItemWidth(160.0f);
        ImGui::SliderFloat("extra latency ms", &extraLatencyMs_, 0.0f, 100.0f, "%.0f");
        ImGui::Checkbox("side-by-side stereo", &stereo_);
        if (stereo_) {
            ImGui::SameLine();
            ImGui::SetNextItemWidth(120.0f);
            ImGui::SliderFloat("IPD mm", &ipdMm_, 50.0f, 80.0f, "%.1f");
        }
        ImGui::Text("eye %dx%d   step-1 horizon %.1f ms", eyeSize.x, eyeSize.y, lastHorizon1_ * 1e3);
        helpTip("from the latest sample fed to the predicted display time");
        ImGui::Text("start->display %.1f ms   re-read->display %.1f ms", startToDisplay_.value * 1e3,
                    rereadToDisplay_.value * 1e3);
        ImGui::Text("step 1 -> 2: %.3f deg   uncovered %llu px", lastDeflectDeg_,
                    static_cast<unsigned long long>(eyes_[0].uncovered));
        helpTip("rotation between the two predictions, which the deflection corrects; output pixels the "
                "deflected image does not cover (border)");
        if (kDeflects[std::size_t(deflect_)] == tracking::Deflect::Shift)
            ImGui::Text("shift %.1f, %.1f px (GL, y up)", lastShift_.x, lastShift_.y);
        ImGui::TextColored(ImVec4(1.0f, 0.85f, 0.3f, 1.0f), "predicted vs true: %.3f deg   %.1f mm", lastErrorDeg_,
                           lastErrorMm_);
        const FrameHistory& sel = historyOf(predictor_, deflect_);
        const FrameHistory& undeflected = historyOf(predictor_, 0);
        char overlay[128];
        std::snprintf(overlay, sizeof overlay, "deg, last %d frames: mean %.3f max %.3f (no deflection %.3f)",
                      sel.count(), sel.mean(), sel.max(), undeflected.mean());
        ImGui::PlotLines("##error", sel.data(), sel.count(), sel.offset(), overlay, 0.0f,
                         std::max(undeflected.max() * 1.1f, 0.01f), ImVec2(ImGui::GetContentRegionAvail().x, 80.0f));
        // Every predictor x deflection on the same motion: mean (max) degrees over the window.
        if (ImGui::BeginTable("errors", 4, ImGuiTableFlags_BordersInnerH | ImGuiTableFlags_SizingStretchProp)) {
            ImGui::TableSetupColumn("predictor");
            for (auto d : kDeflects) ImGui::TableSetupColumn(std::string(tracking::deflectName(d)).c_str());
            ImGui::TableHeadersRow();
            for (std::size_t p = 0; p < names.size(); ++p) {
                ImGui::TableNextRow();
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(names[p].c_str());
                for (std::size_t d = 0; d < kDeflects.size(); ++d) {
                    ImGui::TableNextColumn();
                    const FrameHistory& h = historyOf(int(p), int(d));
                    bool selected = int(p) == predictor_ && int(d) == deflect_;
                    if (selected) ImGui::TextColored(ImVec4(1.0f, 0.85f, 0.3f, 1.0f), "%.3f (%.2f)", h.mean(), h.max());
                    else ImGui::Text("%.3f (%.2f)", h.mean(), h.max());
                }
            }
            ImGui::EndTable();
        }
        ImGui::TextDisabled("mean (max) deg over the last %d frames", FrameHistory::kFrames);
    }
    if (ImGui::CollapsingHeader("GPU time", ImGuiTreeNodeFlags_DefaultOpen)) {
        ImGui::Text("GPU %.3f ms   CPU %.3f ms per eye   %.0f fps", frame_.gpuMs, frame_.cpuMs, ImGui::GetIO().Framerate);
    }
    std::size_t errors = gl::errorCount();
    if (errors) ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.3f, 1.0f), "GL errors: %zu", errors);
    else ImGui::Text("GL errors: 0");
    if (!lastGlError_.empty()) ImGui::TextWrapped("last GL error: %s", lastGlError_.c_str());
    if (!lastError_.empty()) ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.3f, 1.0f), "%s", lastError_.c_str());
    ImGui::End();
}

}  // namespace

int runImmersive(const ViewOptions& options, Scene scene) {
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
    const glm::vec3 firstPosition = tracking::toGlm(measured.front().p);

    WindowSession session(options.width, options.height, "Strata immersive - " + options.scene);
    int status = 0;
    {
        // GL objects die before the context does.
        Immersive immersive(options, std::move(scene), std::move(measured), std::move(truth), truthLabel,
                            session.window());
        immersive.setFirstPosition(firstPosition);
        status = immersive.run();
    }
    std::fflush(stdout);
    return status;
}

}  // namespace strata

#endif  // STRATA_HAVE_TRACKING
