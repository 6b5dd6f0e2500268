// `strata view`: a GLFW window over the same frame pipeline the headless commands use. Each
// frame renders the scene with the chosen technique at the framebuffer size, presents the linear
// output sRGB-encoded, and draws the ImGui panel on top.
#include "view_app.hpp"

#include "camera_controls.hpp"
#include "immersive.hpp"
#include "open_scene.hpp"
#include "panel.hpp"
#include "window_capture.hpp"
#include "window_session.hpp"

#include "camera/camera_path.hpp"
#include "gl/context.hpp"
#include "gl/debug.hpp"
#include "gl/shader_program.hpp"
#include "render/frame_renderer.hpp"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <cmath>
#include <cstdio>
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

// `--set` assignments: `name=value` or `id.name=value`. Strict for the technique the command line
// chose (a typo is an error); lenient on a switch in the panel (names the technique lacks are skipped).
void applyAssignments(Technique& technique, const std::vector<std::string>& assignments, bool strict) {
    const std::string& id = technique.info().id;
    for (const auto& a : assignments) {
        auto dot = a.find('.'), eq = a.find('=');
        if (dot != std::string::npos && eq != std::string::npos && dot < eq) {
            if (a.substr(0, dot) == id) setParameter(technique, a.substr(dot + 1));
            continue;
        }
        if (strict) {
            setParameter(technique, a);
            continue;
        }
        std::string name = a.substr(0, eq);
        for (const auto& p : technique.parameters())
            if (p.name == name) setParameter(technique, a);
    }
}

class Viewer {
public:
    Viewer(const ViewOptions& options, Scene scene, GLFWwindow* window)
        : options_(options), window_(window), scene_(std::move(scene)),
          controls_(defaultCamera(scene_.scene(), scene_.objects()), scene_.bounds()) {
        device_ = gl::currentDeviceInfo();
        techniqueId_ = options.mode;
        technique_ = createTechnique(techniqueId_);
        applyAssignments(*technique_, options.parameters, true);
        present_ = gl::buildProgram({"common/fullscreen.vert.glsl", "frame/present.frag.glsl"});
        recordPath_ = options.recordPath ? *options.recordPath : std::filesystem::path("strata-path.txt");
        if (options.playPath) {
            path_ = CameraPath::read(*options.playPath);
            playing_ = true;
        }
        baseCamera_ = defaultCamera(scene_.scene(), scene_.objects());
    }

    int run() {
        double last = glfwGetTime();
        playOrigin_ = last;
        while (!glfwWindowShouldClose(window_)) {
            glfwPollEvents();
            double now = glfwGetTime();
            double dt = now - last;
            last = now;
            handleKeys();
            applyRequests(now);
            glm::ivec2 size;
            glfwGetFramebufferSize(window_, &size.x, &size.y);
            if (size.x <= 0 || size.y <= 0) {  // minimised
                glfwWaitEvents();
                continue;
            }
            Camera camera = updateCamera(now, dt);
            if (recording_) recorded_.add(now - recordStart_, camera.position, camera.orientation);
            renderFrame(camera, size);
            present(size);
            if (requests_.screenshot) saveOutput();
            requests_ = {};

            bool finalFrame = smokeTest() && frameIndex_ >= std::uint64_t(options_.exitAfterFrames);
            WindowPixels scenePixels;
            if (finalFrame && options_.screenshot) scenePixels = readWindow(size);
            drawImGui(camera, size);
            if (finalFrame) {
                gl::checkGl("view: end of the last frame");
                if (options_.screenshot) saveWindow(*options_.screenshot, scenePixels, size);
                break;
            }
            glfwSwapBuffers(window_);
        }
        if (recording_) stopRecording();
        return 0;
    }

private:
    bool smokeTest() const { return options_.exitAfterFrames > 0; }

    void handleKeys() {
        ImGuiIO& io = ImGui::GetIO();
        for (int key : callbackInput().pressed) {
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
        callbackInput().pressed.clear();
    }

    void applyRequests(double now) {
        if (requests_.technique) switchTechnique(*requests_.technique);
        if (requests_.reload) reload();
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
        // A screenshot waits until this frame is rendered; run() clears the requests then.
    }

    void switchTechnique(const std::string& id) {
        try {
            auto next = createTechnique(id);
            applyAssignments(*next, options_.parameters, false);
            technique_ = std::move(next);
            techniqueId_ = id;
            count_.reset();
            lastError_.clear();
        } catch (const std::exception& e) {
            reportError(std::string("switch to ") + id + ": " + e.what());
        }
    }

    // F5: new technique and renderer, so every program is rebuilt from the files on disk; the
    // technique keeps its parameter values.
    void reload() {
        try {
            auto next = createTechnique(techniqueId_);
            if (technique_) {
                auto old = technique_->parameters();
                for (auto& p : next->parameters())
                    for (const auto& o : old)
                        if (o.name == p.name) *p.value = *o.value;
            }
            gl::Program present = gl::buildProgram({"common/fullscreen.vert.glsl", "frame/present.frag.glsl"});
            technique_ = std::move(next);
            renderer_ = std::make_unique<FrameRenderer>();
            present_ = std::move(present);
            lastError_.clear();
            lastSaved_ = "shaders reloaded";
            std::printf("shaders reloaded\n");
            std::fflush(stdout);
        } catch (const std::exception& e) {
            reportError(std::string("reload: ") + e.what());
        }
    }

    Camera updateCamera(double now, double dt) {
        ImGuiIO& io = ImGui::GetIO();
        NavigationInput input;
        input.dt = dt;
        double x = 0.0, y = 0.0;
        glfwGetCursorPos(window_, &x, &y);
        glm::vec2 cursor{float(x), float(y)};
        glm::vec2 delta = cursor - lastCursor_;
        lastCursor_ = cursor;
        // A drag belongs to the scene when it started outside the panel.
        auto dragging = [&](int button, bool& active) {
            bool down = glfwGetMouseButton(window_, button) == GLFW_PRESS;
            if (!down) active = false;
            else if (!active && !io.WantCaptureMouse) active = true;
            return active;
        };
        if (dragging(GLFW_MOUSE_BUTTON_LEFT, dragLeft_)) input.dragOrbit = delta;
        if (dragging(GLFW_MOUSE_BUTTON_RIGHT, dragRight_)) input.dragLook = delta;
        if (!io.WantCaptureMouse) input.scroll = callbackInput().scroll;
        callbackInput().scroll = 0.0f;
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

    void renderFrame(const Camera& camera, glm::ivec2 size) {
        FrameOptions frameOptions;
        frameOptions.timePasses = true;
        frameOptions.countFragments =
            settings_.countEveryFrame || (settings_.countInterval > 0 && frameIndex_ % std::uint64_t(settings_.countInterval) == 0);
        try {
            frame_ = renderer_->render(scene_, camera, size, technique_.get(), frameOptions);
            if (frame_.fragmentsTotal) count_ = FragmentCount{frameIndex_, *frame_.fragmentsTotal, frame_.stats};
        } catch (const std::exception& e) {
            if (smokeTest()) throw;
            frame_ = {};
            reportError(e.what());
        }
        history_.push(float(frame_.gpuMs));
        ++frameIndex_;
        auto errors = gl::takeErrors();
        if (!errors.empty()) {
            if (smokeTest()) throw std::runtime_error("view: GL error while rendering: " + errors.front());
            lastGlError_ = errors.back();
        }
    }

    void present(glm::ivec2 size) {
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, size.x, size.y);
        glDisable(GL_FRAMEBUFFER_SRGB);
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_BLEND);
        glDisable(GL_CULL_FACE);
        glDisable(GL_SCISSOR_TEST);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glUseProgram(present_.id());
        glBindTextureUnit(0, renderer_->targets().outputColor());
        glBindVertexArray(renderer_->targets().emptyVertexArray());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glBindVertexArray(0);
        glUseProgram(0);
    }

    void drawImGui(const Camera& camera, glm::ivec2 size) {
        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
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
        state.cameraPosition = camera.position;
        state.nearPlane = camera.nearPlane;
        state.farPlane = camera.farPlane;
        state.recording = recording_;
        state.recordedSamples = recorded_.samples().size();
        state.recordPath = recordPath_.string();
        state.hasPath = !path_.empty();
        state.playing = playing_;
        state.pathTime = pathTime_;
        state.pathDuration = path_.duration();
        state.lastError = lastError_;
        state.lastGlError = lastGlError_;
        state.lastSaved = lastSaved_;
        drawPanel(state, settings_, requests_);
        ImGui::Render();
        glViewport(0, 0, size.x, size.y);
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    }

    // F12/P: the final output (linear RGB, sRGB-encoded PNG), without the panel.
    void saveOutput() {
        std::string name = timestampedName("strata-", ".png");
        try {
            writeWindowPng(name, encodeSrgb(renderer_->readOutput()));
            lastSaved_ = "saved " + name;
            std::printf("screenshot: %s\n", std::filesystem::absolute(name).string().c_str());
            std::fflush(stdout);
        } catch (const std::exception& e) {
            reportError(e.what());
        }
    }

    // --screenshot with --exit-after-frames: the whole window as shown, panel included.
    void saveWindow(const std::filesystem::path& path, const WindowPixels& scene, glm::ivec2 size) {
        WindowPixels window = readWindow(size);
        writeWindowPng(path, window);
        std::printf("screenshot: %s %dx%d distinct_colors=%zu scene_colors=%zu panel_pixels=%zu\n",
                    path.string().c_str(), window.width, window.height, distinctColors(window),
                    distinctColors(scene), changedPixels(scene, window));
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
    std::unique_ptr<Technique> technique_;
    std::string techniqueId_;
    gl::Program present_;
    FrameResult frame_;
    FrameHistory history_;
    std::optional<FragmentCount> count_;
    std::uint64_t frameIndex_ = 0;
    PanelSettings settings_;
    PanelRequests requests_;
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
    std::string lastError_, lastGlError_, lastSaved_;
};

}  // namespace

int runViewer(const ViewOptions& options) {
    if (options.trace && !options.immersive) throw std::runtime_error("view: --trace is only used with --immersive");
    if (options.width <= 0 || options.height <= 0)
        throw std::runtime_error("view: window size " + std::to_string(options.width) + "x" +
                                 std::to_string(options.height) + " is not positive");
    if (!findTechnique(options.mode)) createTechnique(options.mode);  // throws, listing the known ids
    Scene scene = openSceneAndWarn(options.scene);                   // bad input fails before a window opens
    if (options.immersive) return runImmersive(options, std::move(scene));  // viewer/immersive.cpp

    GlfwLibrary glfw;
    WindowPtr window = openWindow(options.width, options.height, "Strata - " + options.scene);
    glfwSwapInterval(1);
    gl::installDebugCallback();
    gl::requireCoreFeatures();
    ImGuiSession imgui(window.get());
    int status = 0;
    {
        // GL objects die before the context does.
        Viewer viewer(options, std::move(scene), window.get());
        status = viewer.run();
    }
    std::fflush(stdout);
    return status;
}

bool displayAvailable() { return glfwUsable(); }

}  // namespace strata
