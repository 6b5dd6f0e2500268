// `strata view`: the walkthrough mode of the window loop (viewer/window_loop.hpp) over the same
// frame pipeline the headless commands use. Each frame renders the scene with the chosen
// technique at the framebuffer size, presents the linear output, and draws the panel on top.
#include "view_app.hpp"
#include "lod_panel.hpp"
#include "zoom_driver.hpp"

#include "camera_controls.hpp"
#include "error_view.hpp"
#include "fragment_inspector.hpp"
#include "immersive.hpp"
#include "open_scene.hpp"
#include "panel.hpp"
#include "settings_options.hpp"
#include "split_view.hpp"
#include "window_capture.hpp"
#include "window_loop.hpp"

#include "camera/camera_path.hpp"
#include "gl/context.hpp"
#include "oit/device_defaults.hpp"
#include "render/texture_readback.hpp"
#include "frame/frame_renderer.hpp"
#include "scene/scene_source.hpp"

#include <imgui.h>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <ctime>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace strata {
namespace {

std::string timestampedName(const char* prefix, const char* extension) {
    std::time_t now = std::time(nullptr);
    std::tm local{};
    localtime_r(&now, &local);
    char stamp[32];
    std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &local);
    std::string base = std::string(prefix) + stamp;
    std::string name = base + extension;
    for (int i = 2; std::filesystem::exists(name); ++i) name = base + "-" + std::to_string(i) + extension;
    return name;
}

class WalkthroughMode final : public WindowMode {
public:
    WalkthroughMode(const ViewOptions& options, Scene scene, GLFWwindow* window)
        : options_(options), window_(window), scene_(std::move(scene)),
          controls_(defaultCamera(scene_.scene(), scene_.objects()), scene_.bounds()) {
        device_ = gl::currentDeviceInfo();
        techniqueId_ = options.mode;
        techniqueSettings_ = viewSettings(options, device_);
        technique_ = createConfiguredTechnique(techniqueId_, techniqueSettings_);
        settings_.technique = technique_->settings();
        settings_.view = options.view;
        zoom_.choices() = zoomChoicesFrom(options);
        // Interactive: a frame starts no impostor bake past its budget (one at least); objects
        // draw their geometry until their impostor is ready, and the panel says how many wait.
        lod_ = makeWindowLod(scene_, options.lod);
        recordPath_ = options.recordPath ? *options.recordPath : std::filesystem::path("strata-path.txt");
        if (options.playPath) {
            path_ = CameraPath::read(*options.playPath);
            playing_ = true;
        }
        baseCamera_ = defaultCamera(scene_.scene(), scene_.objects());
        split_ = std::make_unique<SplitView>(options.splitWith, options.splitAt, techniqueSettings_);
        if (options.inspect) inspector_.select(*options.inspect);
    }

    void start(double now) override { playOrigin_ = now; }

    void update(double now, double dt, const CallbackInput& input) override {
        handleKeys(input.pressed);
        applyRequests(now);
        camera_ = updateCamera(now, dt, input.scroll);
        if (recording_) recorded_.add(now - recordStart_, camera_.position, camera_.orientation);
    }

    void render(glm::ivec2 size, Presenter& presenter) override {
        if (requests_.reload) reload(presenter);
        renderFrame(size);
        renderViews(size);
        const PresentRegion output{shownTexture(), {0, 0}, size};
        presenter.present(size, {&output, 1});
        if (requests_.screenshot) saveOutput();
        requests_ = {};
    }

    void drawPanel(glm::ivec2 size, const std::string& lastGlError) override {
        PanelState state;
        state.scene = &scene_;
        state.device = &device_;
        state.technique = technique_.get();
        state.techniqueId = techniqueId_;
        state.frame = &frame_;
        state.history = &history_;
        state.count = count_;
        state.frameIndex = frameIndex_;
        state.size = size;
        state.navigation = playing_ ? "camera path" : controls_.modeName();
        state.cameraPosition = camera_.position;
        state.nearPlane = camera_.nearPlane;
        state.farPlane = camera_.farPlane;
        state.recording = recording_;
        state.recordedSamples = recorded_.samples().size();
        state.recordPath = recordPath_.string();
        state.hasPath = !path_.empty();
        state.playing = playing_;
        state.pathTime = pathTime_;
        state.pathDuration = path_.duration();
        state.lastError = lastError_;
        state.lastGlError = lastGlError;
        state.lastSaved = lastSaved_;
        state.zoom = &zoom_;
        state.lod = lod_.get();
        state.viewDetails = [this] { drawViewDetails(); };
        strata::drawPanel(state, settings_, requests_);
        inspector_.drawWindow(scene_);
    }

    void reportLastFrame() override {
        if (showingError()) errorView_->printFigures(techniqueId_.c_str(), lastSize_);
        if (settings_.view == ViewKind::Split) split_->printFigures(lastSize_);
        inspector_.printFigures(scene_);
        zoom_.printFigures();
        printLodFigures(*lod_);
        std::fflush(stdout);
    }

    void stop() override {
        if (recording_) stopRecording();
    }

private:
    bool smokeTest() const { return options_.exitAfterFrames > 0; }

    void handleKeys(const std::vector<int>& pressed) {
        ImGuiIO& io = ImGui::GetIO();
        for (int key : pressed) {
            bool typing = io.WantTextInput;
            switch (key) {
            case GLFW_KEY_F12: requests_.screenshot = true; break;
            case GLFW_KEY_F5: requests_.reload = true; break;
            case GLFW_KEY_P: if (!typing) requests_.screenshot = true; break;
            case GLFW_KEY_R: if (!typing) requests_.toggleRecording = true; break;
            case GLFW_KEY_SPACE: if (!typing) requests_.togglePlayback = true; break;
            case GLFW_KEY_TAB: if (!typing && !io.WantCaptureKeyboard) requests_.toggleNavigation = true; break;
            default: break;
            }
        }
    }

    void applyRequests(double now) {
        if (requests_.technique) switchTechnique(*requests_.technique);
        if (splitRequest_) {
            try {
                split_->setTechnique(*splitRequest_, techniqueSettings_);
            } catch (const std::exception& e) {
                reportError("split with " + *splitRequest_ + ": " + e.what());
            }
            splitRequest_.reset();
        }
        if (requests_.toggleNavigation) controls_.toggleMode();
        if (requests_.vsyncChanged) glfwSwapInterval(settings_.vsync ? 1 : 0);
        if (requests_.toggleRecording) {
            if (recording_) stopRecording();
            else {
                recorded_ = CameraPath();
                recordStart_ = now;
                recording_ = true;
                std::printf("recording camera path to %s\n", recordPath_.string().c_str());
                std::fflush(stdout);
            }
        }
        if (requests_.togglePlayback && !path_.empty()) {
            if (playing_) playing_ = false;
            else {
                playOrigin_ = now - (pathTime_ - path_.startTime());
                playing_ = true;
            }
        }
        // A reload and a screenshot wait for render(), which clears the requests.
    }

    void switchTechnique(const std::string& id) {
        try {
            auto next = createConfiguredTechnique(id, techniqueSettings_);
            technique_ = std::move(next);
            techniqueId_ = id;
            settings_.technique = technique_->settings();
            count_.reset();
            lastError_.clear();
        } catch (const std::exception& e) {
            reportError(std::string("switch to ") + id + ": " + e.what());
        }
    }

    // F5: new technique, renderer and present program, so every program is rebuilt from the
    // files on disk; the technique keeps its settings. Nothing changes when one fails to build.
    void reload(Presenter& presenter) {
        try {
            auto next = createConfiguredTechnique(techniqueId_, techniqueSettings_);
            presenter.reload();
            technique_ = std::move(next);
            renderer_ = std::make_unique<FrameRenderer>();
            lastError_.clear();
            lastSaved_ = "shaders reloaded";
            std::printf("shaders reloaded\n");
            std::fflush(stdout);
        } catch (const std::exception& e) {
            reportError(std::string("reload: ") + e.what());
        }
    }

    Camera updateCamera(double now, double dt, float scroll) {
        ImGuiIO& io = ImGui::GetIO();
        NavigationInput input;
        input.dt = dt;
        double x = 0.0, y = 0.0;
        glfwGetCursorPos(window_, &x, &y);
        glm::vec2 cursor{float(x), float(y)};
        glm::vec2 delta = cursor - lastCursor_;
        lastCursor_ = cursor;
        // The split view's divider and a click on a pixel (the fragment inspector) take the left
        // button before the camera does; a drag that is neither orbits.
        const bool leftDown = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
        const bool dividerDrag = settings_.view == ViewKind::Split &&
                                 split_->handleMouse(cursor, leftDown, io.WantCaptureMouse, windowSize());
        if (auto click = clicks_.update(cursor, leftDown, io.WantCaptureMouse); click && !dividerDrag)
            inspector_.select(glm::ivec2(*click));
        // A drag belongs to the scene when it started outside the panel.
        auto dragging = [&](int button, bool& active) {
            bool down = glfwGetMouseButton(window_, button) == GLFW_PRESS;
            if (!down) active = false;
            else if (!active && !io.WantCaptureMouse) active = true;
            return active;
        };
        if (!dividerDrag && dragging(GLFW_MOUSE_BUTTON_LEFT, dragLeft_)) input.dragOrbit = delta;
        if (dragging(GLFW_MOUSE_BUTTON_RIGHT, dragRight_)) input.dragLook = delta;
        if (!io.WantCaptureMouse) input.scroll = scroll;
        if (!io.WantCaptureKeyboard) {
            auto held = [&](int key) { return glfwGetKey(window_, key) == GLFW_PRESS ? 1.0f : 0.0f; };
            input.move = {held(GLFW_KEY_D) - held(GLFW_KEY_A), held(GLFW_KEY_E) - held(GLFW_KEY_Q),
                          held(GLFW_KEY_W) - held(GLFW_KEY_S)};
            input.fast = held(GLFW_KEY_LEFT_SHIFT) + held(GLFW_KEY_RIGHT_SHIFT) > 0.0f;
        }
        if (!path_.empty()) {
            if (playing_) {
                double duration = path_.duration();
                pathTime_ = path_.startTime() + (duration > 0.0 ? std::fmod(now - playOrigin_, duration) : 0.0);
            }
            if (playing_) {
                Camera c = cameraAt(path_, pathTime_, baseCamera_);
                controls_.setPose(c.position, c.orientation);
                c.fitClipPlanes(scene_.bounds());
                return c;
            }
        }
        controls_.update(input);
        return controls_.camera();
    }

    bool showingHeatmap() const {
        return settings_.view == ViewKind::CoplanarityHeatmap && frame_.coplanarity && renderer_->coplanarity();
    }

    bool showingError() const { return settings_.view == ViewKind::Error && errorView_ && errorShown_; }
    bool showingSplit() const { return settings_.view == ViewKind::Split && splitShown_; }

    // The frame's output, or what the chosen view made of it when this frame made it.
    GLuint shownTexture() const {
        if (showingHeatmap()) return renderer_->coplanarity()->heatmapTexture();
        if (showingError()) return errorView_->falseColor();
        if (showingSplit()) return split_->composite();
        return renderer_->outputColor();
    }

    glm::vec2 windowSize() const {
        int w = 0, h = 0;
        glfwGetWindowSize(window_, &w, &h);
        return {float(w), float(h)};
    }

    // After the technique's frame: the reference and error image, the split's B half, and the
    // inspected pixel, each only while it is shown.
    void renderViews(glm::ivec2 size) {
        lastSize_ = size;
        errorShown_ = splitShown_ = false;
        if (!frameOk_) return;
        // At a zoom, the enlarged frame: the error view then shows what the zoom loses too.
        const GLuint output = renderer_->outputColor();
        try {
            if (settings_.view == ViewKind::Error || settings_.view == ViewKind::Split) {
                if (!errorView_) errorView_ = std::make_unique<ErrorView>();
                errorView_->renderReference(scene_, camera_, size, frameIndex_);
            }
            if (settings_.view == ViewKind::Error) {
                errorView_->compare(output, size, true);
                errorShown_ = true;
            }
            if (settings_.view == ViewKind::Split) {
                split_->render(scene_, camera_, size, frameIndex_, techniqueId_, output, frame_, *errorView_,
                               standIns_);
                splitShown_ = true;
            }
            inspector_.inspect(scene_, camera_, size, windowSize(), output, techniqueId_, frame_.stats);
        } catch (const std::exception& e) {
            if (smokeTest()) throw;
            reportError(e.what());
        }
    }

    void drawViewDetails() {
        if (settings_.view == ViewKind::Error && errorView_) errorView_->drawPanel(techniqueId_.c_str());
        if (settings_.view == ViewKind::Split) split_->drawPanel(splitRequest_);
        ImGui::TextDisabled("click a pixel: its fragments, and which the technique kept");
    }

    void renderFrame(glm::ivec2 size) {
        FrameOptions frameOptions;
        frameOptions.timePasses = true;
        // Live: the detector runs on every frame while its view is shown, never otherwise.
        frameOptions.detectCoplanarity = settings_.view == ViewKind::CoplanarityHeatmap;
        frameOptions.countFragments =
            settings_.countEveryFrame || (settings_.countInterval > 0 && frameIndex_ % std::uint64_t(settings_.countInterval) == 0);
        // The panel edited a copy; it takes effect here, between frames, where it differs from
        // what the last frame used (the technique reallocates what the change needs).
        if (technique_ && settings_.technique != technique_->settings()) {
            technique_->setSettings(settings_.technique);
            techniqueSettings_[techniqueId_] = settings_.technique;
        }
        try {
            frameOk_ = false;
            // A failed bake or calibration (an edited shader) is reported like a failed frame.
            standIns_ = nullptr;
            zoom_.begin(scene_, camera_, size, technique_.get(), frameOptions, 0.0, lod_.get());
            // The heatmap is of the frame drawn: shown at the window's size, it needs zoom 1.
            if (frameOptions.detectCoplanarity) frameOptions.zoom = 1;
            frameOptions.standIns = standIns_ = lod_->select(camera_, size);
            frame_ = renderer_->render(scene_, camera_, size, technique_.get(), frameOptions);
            zoom_.end(frame_, technique_.get());
            frameOk_ = true;
            if (frame_.fragmentsTotal) count_ = FragmentCount{frameIndex_, *frame_.fragmentsTotal, frame_.stats};
        } catch (const std::exception& e) {
            if (smokeTest()) throw;
            frame_ = {};
            reportError(e.what());
        }
        history_.push(float(frame_.gpuMs));
        ++frameIndex_;
    }

    // F12/P: what the view shows (linear RGB, sRGB-encoded PNG), without the panel.
    void saveOutput() {
        const bool plain = shownTexture() == renderer_->outputColor();
        std::string prefix = plain ? "strata-" : std::string("strata-") + viewName(settings_.view) + "-";
        std::string name = timestampedName(prefix.c_str(), ".png");
        try {
            const Image shown = readRgbaTexture(shownTexture(), lastSize_);
            writeWindowPng(name, encodeSrgb(shown));
            lastSaved_ = "saved " + name;
            std::printf("screenshot: %s\n", std::filesystem::absolute(name).string().c_str());
            std::fflush(stdout);
        } catch (const std::exception& e) {
            reportError(e.what());
        }
    }

    void stopRecording() {
        recording_ = false;
        if (recorded_.empty()) {
            lastSaved_ = "nothing recorded";
            return;
        }
        try {
            recorded_.write(recordPath_);
            lastSaved_ = "wrote " + std::to_string(recorded_.samples().size()) + " samples to " + recordPath_.string();
            std::printf("camera path: %s (%zu samples, %.2f s)\n", recordPath_.string().c_str(),
                        recorded_.samples().size(), recorded_.duration());
            std::fflush(stdout);
        } catch (const std::exception& e) {
            reportError(e.what());
        }
    }

    void reportError(const std::string& message) {
        if (message != lastError_) std::fprintf(stderr, "strata view: %s\n", message.c_str());
        lastError_ = message;
    }

    const ViewOptions& options_;
    GLFWwindow* window_;
    gl::DeviceInfo device_;
    GpuScene scene_;
    CameraControls controls_;
    Camera baseCamera_;
    std::unique_ptr<FrameRenderer> renderer_ = std::make_unique<FrameRenderer>();
    ZoomDriver zoom_;
    std::unique_ptr<lod::LodController> lod_;  // per-object geometry or impostor, every frame
    const StandIns* standIns_ = nullptr;       // this frame's, from lod_
    std::unique_ptr<Technique> technique_;
    std::string techniqueId_;
    Camera camera_;  // this frame's, from update()
    FrameResult frame_;
    FrameHistory history_;
    std::optional<FragmentCount> count_;
    std::uint64_t frameIndex_ = 0;
    PanelSettings settings_;
    SettingsById techniqueSettings_;  // each technique's, kept across switches and reloads
    PanelRequests requests_;
    // The error, split and inspector views (viewer/error_view.hpp, split_view.hpp,
    // fragment_inspector.hpp); the reference renders only while a view needs it.
    std::unique_ptr<ErrorView> errorView_;
    std::unique_ptr<SplitView> split_;
    std::optional<std::string> splitRequest_;
    FragmentInspector inspector_;
    ClickDetector clicks_;
    bool frameOk_ = false, errorShown_ = false, splitShown_ = false;
    glm::ivec2 lastSize_{0};
    glm::vec2 lastCursor_{0.0f};
    bool dragLeft_ = false, dragRight_ = false;
    // Camera paths.
    CameraPath path_;
    bool playing_ = false;
    double playOrigin_ = 0.0, pathTime_ = 0.0;
    CameraPath recorded_;
    bool recording_ = false;
    double recordStart_ = 0.0;
    std::filesystem::path recordPath_;
    // Messages for the panel.
    std::string lastError_, lastSaved_;
};

WindowModeFactory walkthroughMode(const ViewOptions& options, Scene scene) {
    return [&options, scene = std::move(scene)](GLFWwindow* window) mutable {
        return std::make_unique<WalkthroughMode>(options, std::move(scene), window);
    };
}

}  // namespace

SettingsById viewSettings(const ViewOptions& options, const gl::DeviceInfo& device) {
    return options.deviceDefaults ? resolveSettingsForDevice(allTechniqueIds(), options.settingAssignments, device)
                                  : resolveSettings(allTechniqueIds(), options.settingAssignments);
}

int runViewer(const ViewOptions& options) {
    if (options.trace && !options.immersive) throw std::runtime_error("view: --trace is only used with --immersive");
    if (options.width <= 0 || options.height <= 0)
        throw std::runtime_error("view: window size " + std::to_string(options.width) + "x" +
                                 std::to_string(options.height) + " is not positive");
    if (!findTechnique(options.mode)) createTechnique(options.mode);  // throws, listing the known ids
    Scene scene = openSceneAndWarn(options.scene);                          // bad input fails before a window opens
    const bool immersive = options.immersive;
    WindowModeFactory makeMode = immersive ? immersiveMode(options, std::move(scene))  // viewer/immersive.cpp
                                           : walkthroughMode(options, std::move(scene));
    WindowLoopOptions loop{.width = options.width,
                           .height = options.height,
                           .title = (immersive ? "Strata immersive - " : "Strata - ") + options.scene,
                           .name = immersive ? "view --immersive" : "view",
                           .exitAfterFrames = options.exitAfterFrames,
                           .screenshot = options.screenshot};
    return runWindowLoop(loop, makeMode);
}

bool displayAvailable() { return glfwUsable(); }

}  // namespace strata
