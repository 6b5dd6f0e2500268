#pragma once
// Shared by the *_gl_test.cpp files: one headless GL context for the test process, and helpers
// that render a scene with a technique and read the frame back.
#include "camera/camera.hpp"
#include "gl/context.hpp"
#include "gl/debug.hpp"
#include "image/image.hpp"
#include "oit/technique.hpp"
#include "oit/technique_settings.hpp"
#include "frame/frame_renderer.hpp"
#include "reference/raycast.hpp"
#include "render/gpu_scene.hpp"
#include "render/shading.hpp"

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace strata::test {

// Created on first use; KHR_debug errors are recorded and `gl::checkGl` turns them into
// exceptions, which the helpers below call after every GL step.
inline gl::HeadlessContext& glContext() {
    static gl::HeadlessContext context;
    return context;
}

// Applies "[id.]name=value" to a technique through the path the command line takes.
inline void setSetting(Technique& technique, const std::string& assignment) {
    applySettings(technique, {{assignment, "test"}});
}

// Technique `id` with "name=value" settings.
inline std::unique_ptr<Technique> makeTechnique(const std::string& id, const std::vector<std::string>& settings = {}) {
    auto t = createTechnique(id);
    for (const auto& s : settings) setSetting(*t, s);
    return t;
}

// Whether technique `id` has a setting called `name` (read from the registry, no GL needed).
inline bool hasSetting(const std::string& id, const std::string& name) {
    for (const auto& d : findTechnique(id)->settings)
        if (d.name == name) return true;
    return false;
}

struct Rendered {
    Image image;
    FrameResult result;
};

inline Rendered renderWith(const GpuScene& scene, const Camera& camera, glm::ivec2 size, Technique& technique,
                           FrameOptions options = {}) {
    glContext();
    FrameRenderer renderer;
    options.countFragments = true;
    Rendered r;
    r.result = renderer.render(scene, camera, size, &technique, options);
    gl::checkGl("render");
    r.image = renderer.readOutput();
    gl::checkGl("read back");
    return r;
}

inline Rendered renderWith(const GpuScene& scene, const Camera& camera, glm::ivec2 size, const std::string& id,
                           FrameOptions options = {}) {
    glContext();
    auto technique = createTechnique(id);
    return renderWith(scene, camera, size, *technique, options);
}

// A scene on the GPU with the camera it suggests.
struct Fixture {
    std::unique_ptr<GpuScene> gpu;
    Camera camera;
    explicit Fixture(Scene s) {
        glContext();
        gpu = std::make_unique<GpuScene>(std::move(s));
        camera = defaultCamera(gpu->scene(), gpu->objects());
    }
};

// The colour a lit rough dielectric of base colour `base`, facing +z, shows at pixel (x, y) of
// a `size` image: common/shading_model.h seen along that pixel's ray, under the scene's light.
// What a closed-form composite of builtin scenes' facing quads (builtin:coplanar) takes per layer.
inline glm::vec3 litFacing(const Scene& scene, const Camera& camera, glm::ivec2 size, int x, int y, glm::vec3 base) {
    glm::dvec3 origin, direction;
    pixelRay(camera, size.x, size.y, x, y, origin, direction);
    return shadeSurface(base, 0.0f, 1.0f, 1.0f, glm::vec3(0.0f), {0.0f, 0.0f, 1.0f}, glm::vec3(-glm::normalize(direction)),
                        scene.lightDirection, glm::vec3(kDefaultLightIrradiance));
}

// With STRATA_TEST_DUMP naming a folder, writes `image` there as NAME.exr (float, linear), so
// a failure on a machine that cannot be debugged in place (a lent GPU) comes back as pictures.
// Call it where a check has failed; without the variable it does nothing.
inline void dumpImage(const std::string& name, const Image& image) {
    const char* dir = std::getenv("STRATA_TEST_DUMP");
    if (!dir || !*dir) return;
    std::filesystem::create_directories(dir);
    std::string file;
    for (char c : name) file += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.' ? c : '_';
    writeImage(std::filesystem::path(dir) / (file + ".exr"), image);
}

}  // namespace strata::test
