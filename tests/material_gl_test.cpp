// The per-object material path delivers the volume parameters (Material::tau and albedo) to the
// shaders: a test stage writes them out and they are read back per object.
#include "test_paths.hpp"
#include "gl_test_support.hpp"

#include "render/scene_program.hpp"
#include "scene/builtin_scenes.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <set>
#include <vector>

using namespace strata;

namespace {

constexpr int kTargets = 3;  // tau, albedo, volumeTransmittance(0.5)

struct Probe {
    std::vector<glm::vec4> target[kTargets];
};

// Draws object `index` alone into cleared RGBA32F targets and reads them back. Alpha is 1
// where the object was drawn and -1 elsewhere.
Probe drawAlone(const GpuScene& scene, const SceneProgram& program, const Camera& camera, glm::ivec2 size,
                int index) {
    gl::Texture textures[kTargets];
    gl::Framebuffer fbo = gl::Framebuffer::create();
    GLenum buffers[kTargets];
    for (int t = 0; t < kTargets; ++t) {
        textures[t] = gl::createTexture2D(GL_RGBA32F, size.x, size.y);
        glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0 + t, textures[t].id(), 0);
        buffers[t] = GL_COLOR_ATTACHMENT0 + t;
    }
    glNamedFramebufferDrawBuffers(fbo.id(), kTargets, buffers);
    const float clear[4] = {-1.0f, -1.0f, -1.0f, -1.0f};
    for (int t = 0; t < kTargets; ++t) glClearNamedFramebufferfv(fbo.id(), GL_COLOR, t, clear);

    glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
    glViewport(0, 0, size.x, size.y);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glUseProgram(program.id());
    scene.setFrameUniforms(program, camera.projection(float(size.x) / float(size.y)) * camera.view());
    scene.draw(program, index);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    gl::checkGl("material probe");

    Probe p;
    for (int t = 0; t < kTargets; ++t) {
        p.target[t].resize(std::size_t(size.x) * std::size_t(size.y));
        glGetTextureImage(textures[t].id(), 0, GL_RGBA, GL_FLOAT, GLsizei(p.target[t].size() * sizeof(glm::vec4)),
                          p.target[t].data());
    }
    gl::checkGl("material probe read back");
    return p;
}

}  // namespace

TEST_CASE("tau and albedo of each builtin:volumes object reach the shaders through the material path") {
    test::Fixture f(makeVolumesScene());
    const std::string probe = (test::sourceDir() / "tests/shaders/material_probe.frag.glsl").string();
    SceneProgram program = buildSceneProgram(probe);
    REQUIRE(program.tau >= 0);
    REQUIRE(program.albedo >= 0);
    const glm::ivec2 size(32, 24);
    std::set<std::vector<float>> distinctTau;
    int volumes = 0;
    for (std::size_t index = 0; index < f.gpu->objects().size(); ++index) {
        const Object& o = f.gpu->objects()[index];
        const Material& m = f.gpu->scene().materials[std::size_t(o.material)];
        CAPTURE(m.name);
        if (m.tau != glm::vec3(0.0f)) ++volumes;
        distinctTau.insert({m.tau.x, m.tau.y, m.tau.z});
        Probe p = drawAlone(*f.gpu, program, f.camera, size, int(index));
        int covered = 0;
        for (std::size_t i = 0; i < p.target[0].size(); ++i) {
            if (p.target[0][i].a != 1.0f) continue;
            ++covered;
            // A uniform carries a float unchanged: the values are the material's, bit for bit.
            CHECK(glm::vec3(p.target[0][i]) == m.tau);
            CHECK(glm::vec3(p.target[1][i]) == m.albedo);
            for (int c = 0; c < 3; ++c)
                CHECK(p.target[2][i][c] == doctest::Approx(std::exp(-0.5 * double(m.tau[c]))).epsilon(1e-5));
            if (covered > 8) break;  // the values are per object; a few pixels show them
        }
        CHECK(covered > 0);
    }
    // The scene holds three volumes with different tau (and a floor with none): the check above
    // would catch one object's values given to another.
    CHECK(volumes == 3);
    CHECK(distinctTau.size() == 4);
}
