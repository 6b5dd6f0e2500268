// Objects that share a mesh and a material are drawn by one instanced draw
// (GpuScene::drawObjects), each with its own transform, id and volume values from its record
// (render/object_records.hpp): the image is the one a draw per object gives, and the GL draw
// count is the number of batches.
#include "gl_test_support.hpp"
#include "test_paths.hpp"

#include "render/scene_program.hpp"
#include "render/texture_readback.hpp"
#include "scene/mesh_builders.hpp"

#include <doctest/doctest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <vector>

using namespace strata;

namespace {

constexpr int kRow = 6;  // quads of mesh A in a row, then two of mesh B

// Mesh A placed kRow times along x with material 0; then mesh B (a smaller quad) twice, above
// them, with material 1. Objects 0 .. kRow-1 are A, kRow and kRow+1 are B. Both materials are
// unlit, so a pixel's colour is the base colour exactly.
Scene rowScene() {
    Scene s;
    const int quadA = s.addMesh(makeQuad(0.8f, 0.8f));
    const int quadB = s.addMesh(makeQuad(0.5f, 0.5f));
    for (int k = 0; k < 2; ++k) {
        Material m;
        m.name = k == 0 ? "a" : "b";
        m.unlit = true;
        m.baseColor = k == 0 ? glm::vec3(0.2f, 0.7f, 0.4f) : glm::vec3(0.9f, 0.3f, 0.1f);
        m.alpha = k == 0 ? 0.25f : 0.75f;
        s.materials.push_back(m);
    }
    for (int i = 0; i < kRow + 2; ++i) {
        Node n;
        const bool a = i < kRow;
        n.meshes = {a ? quadA : quadB};
        n.materialOverride = a ? 0 : 1;
        n.local = glm::translate(glm::mat4(1.0f), a ? glm::vec3(float(i) - 2.5f, 0.0f, 0.0f)
                                                    : glm::vec3(float(i - kRow) * 2.0f - 1.0f, 1.2f, 0.0f));
        s.addNode(std::move(n));
    }
    return s;
}

struct Target {
    gl::Texture color;
    gl::Framebuffer fbo;
    glm::ivec2 size;
    explicit Target(glm::ivec2 s) : size(s) {
        color = gl::createTexture2D(GL_RGBA32F, size.x, size.y);
        fbo = gl::Framebuffer::create();
        glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, color.id(), 0);
    }
    void begin() const {
        const float clear[4] = {0.0f, 0.0f, 0.0f, 0.0f};
        glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, clear);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
        glViewport(0, 0, size.x, size.y);
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_BLEND);
        glDisable(GL_CULL_FACE);
    }
    Image read() const {
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        return readRgbaTexture(color.id(), size);
    }
};

glm::vec3 pixel(const Image& image, int x, int y) {
    const std::size_t i = (std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 4;
    return {image.rgba[i], image.rgba[i + 1], image.rgba[i + 2]};
}

// Where object `o`'s centre lands in the image.
glm::ivec2 centreOf(const GpuScene& scene, const glm::mat4& viewProjection, glm::ivec2 size, int o) {
    const glm::vec4 clip = viewProjection * glm::vec4(scene.objects()[std::size_t(o)].worldBounds.center(), 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return glm::ivec2((ndc * 0.5f + 0.5f) * glm::vec2(size));
}

// Objects 0 .. count-1 each where its own transform puts it, in its own material's colour.
void checkOwnColours(const GpuScene& scene, const Image& image, const glm::mat4& viewProjection, int count) {
    for (int o = 0; o < count; ++o) {
        CAPTURE(o);
        const glm::ivec2 at = centreOf(scene, viewProjection, {image.width, image.height}, o);
        const Material& m = scene.scene().materials[std::size_t(scene.objects()[std::size_t(o)].material)];
        for (int c = 0; c < 3; ++c) CHECK(pixel(image, at.x, at.y)[c] == doctest::Approx(m.baseColor[c]).epsilon(1e-5));
    }
}

}  // namespace

TEST_CASE("objects sharing a mesh and material draw as one instanced draw, each with its own transform and id") {
    test::Fixture f(rowScene());
    const GpuScene& scene = *f.gpu;
    REQUIRE(scene.objects().size() == std::size_t(kRow + 2));
    const SceneProgram program = buildSceneProgram("common/opaque.frag.glsl");
    const glm::ivec2 size(96, 48);
    Camera camera;
    camera.fovYDegrees = 60.0f;
    camera.lookAt({0.0f, 0.4f, 5.0f}, {0.0f, 0.4f, 0.0f});
    const glm::mat4 viewProjection = camera.projection(float(size.x) / float(size.y)) * camera.view();
    Target target(size);

    // One object per draw.
    target.begin();
    glUseProgram(program.id());
    scene.setFrameUniforms(program, viewProjection);
    std::uint64_t before = scene.drawCalls();
    for (int o = 0; o < kRow + 2; ++o) scene.draw(program, o);
    CHECK(scene.drawCalls() - before == std::uint64_t(kRow + 2));
    const Image single = target.read();

    // The same objects batched: the six A quads in one draw, the two B quads in another.
    std::vector<int> order;
    for (int o = 0; o < kRow + 2; ++o) order.push_back(o);
    target.begin();
    glUseProgram(program.id());
    scene.setFrameUniforms(program, viewProjection);
    CHECK(scene.drawObjects(program, order) == 2);
    const Image batched = target.read();
    gl::checkGl("instanced draws");

    // Every object where its own transform puts it, in its own material's colour, in both images.
    checkOwnColours(scene, single, viewProjection, kRow + 2);
    checkOwnColours(scene, batched, viewProjection, kRow + 2);
    double largest = 0.0;
    for (std::size_t i = 0; i < single.rgba.size(); ++i)
        largest = std::max(largest, double(std::abs(single.rgba[i] - batched.rgba[i])));
    CHECK(largest <= 1e-6);

    // The probe stage writes what reached the fragment stage: each instance's own id (its
    // record) and its batch's alpha (the material's uniform).
    const SceneProgram probe = buildSceneProgram((test::sourceDir() / "tests/shaders/object_probe.frag.glsl").string());
    target.begin();
    glUseProgram(probe.id());
    scene.setFrameUniforms(probe, viewProjection);
    CHECK(scene.drawObjects(probe, order) == 2);
    const Image ids = target.read();
    gl::checkGl("probe");
    for (int o = 0; o < kRow + 2; ++o) {
        CAPTURE(o);
        const glm::ivec2 at = centreOf(scene, viewProjection, size, o);
        const glm::vec3 got = pixel(ids, at.x, at.y);
        CHECK(got.x == float(scene.objects()[std::size_t(o)].id));
        CHECK(got.y == 0.0f);  // a thin surface
        CHECK(got.z == (o < kRow ? 0.25f : 0.75f));
        const std::size_t i = (std::size_t(at.y) * std::size_t(size.x) + std::size_t(at.x)) * 4;
        CHECK(ids.rgba[i + 3] <= 1.0f);  // a quad's two triangles: 0 or 1 in every instance
    }
}

TEST_CASE("a run breaks where the mesh changes; the batched order groups each mesh's objects") {
    test::Fixture f(rowScene());
    const GpuScene& scene = *f.gpu;
    const SceneProgram program = buildSceneProgram("common/opaque.frag.glsl");
    Target target({32, 16});
    target.begin();
    glUseProgram(program.id());
    scene.setFrameUniforms(program, glm::mat4(1.0f));
    // A A B A B: four runs in this order.
    CHECK(scene.drawObjects(program, {0, 1, kRow, 2, kRow + 1}) == 4);
    CHECK(scene.sameBatch(0, 5));
    CHECK_FALSE(scene.sameBatch(0, kRow));
    // The scene's batched list puts the As, then the Bs, together: two draws.
    const std::vector<int>& batched = scene.opaqueObjectsBatched();
    REQUIRE(batched.size() == std::size_t(kRow + 2));
    CHECK(scene.drawObjects(program, batched) == 2);
    target.read();
    gl::checkGl("runs");
}

TEST_CASE("the object stream's ring wraps without disturbing the draws already issued") {
    // The ring holds 1024 entries for a small scene: 400 passes of 6 objects wrap it twice, and
    // the last pass's draw must still read its own six entries.
    test::Fixture f(rowScene());
    const GpuScene& scene = *f.gpu;
    const SceneProgram program = buildSceneProgram("common/opaque.frag.glsl");
    const glm::ivec2 size(64, 32);
    Camera camera;
    camera.fovYDegrees = 60.0f;
    camera.lookAt({0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, 0.0f});
    const glm::mat4 viewProjection = camera.projection(float(size.x) / float(size.y)) * camera.view();
    const std::vector<int> row = {5, 3, 1, 0, 2, 4};  // not consecutive: through the ring
    Target target(size);
    target.begin();
    glUseProgram(program.id());
    for (int pass = 0; pass < 400; ++pass) {
        scene.setFrameUniforms(program, viewProjection);
        CHECK(scene.drawObjects(program, row) == 1);
    }
    const Image image = target.read();
    gl::checkGl("ring");
    checkOwnColours(scene, image, viewProjection, kRow);
}
