// The exact reference on the GPU against the CPU ray cast and closed forms.
#include "gl_test_support.hpp"

#include "reference/raycast.hpp"
#include "render/composite.hpp"
#include "render/shading.hpp"
#include "scene/builtin_scenes.hpp"
#include "scene/mesh_builders.hpp"

#include <doctest/doctest.h>
#include <glm/gtc/matrix_transform.hpp>

using namespace strata;

namespace {

constexpr float kTolerance = 1.0f / 255.0f;  // one 8-bit step: the contract for exact techniques

struct Fixture {
    Scene scene;
    std::unique_ptr<GpuScene> gpu;
    Camera camera;
    explicit Fixture(Scene s) : scene(s) {
        test::glContext();
        gpu = std::make_unique<GpuScene>(std::move(s));
        camera = defaultCamera(gpu->scene(), gpu->objects());
    }
};

}  // namespace

TEST_CASE("abuffer equals the CPU ray-cast reference on N full-view layers") {
    for (int n : {1, 2, 8}) {
        CAPTURE(n);
        Fixture f(makeLayersScene(n));
        glm::ivec2 size(48, 32);
        auto gpu = test::renderWith(*f.gpu, f.camera, size, "abuffer");
        Image cpu = raycastReference(f.gpu->scene(), f.gpu->objects(), f.camera, size.x, size.y);
        auto diff = compareImages(gpu.image, cpu, kTolerance);
        CHECK(diff.maxAbsError <= kTolerance);
        CHECK(diff.pixelsOver == 0);
        // Depth complexity exactly n everywhere: the shared count and the captured count agree.
        REQUIRE(gpu.result.fragmentsTotal.has_value());
        CHECK(*gpu.result.fragmentsTotal == std::uint64_t(n) * size.x * size.y);
        CHECK(gpu.result.stats.fragmentsCaptured == std::uint64_t(n) * size.x * size.y);
        CHECK_FALSE(gpu.result.stats.overflowed);
    }
}

TEST_CASE("blend-sorted equals abuffer on layers; blend-unsorted, drawn front to back, does not") {
    for (int n : {1, 2, 8}) {
        CAPTURE(n);
        Fixture f(makeLayersScene(n));
        glm::ivec2 size(32, 32);
        Image exact = test::renderWith(*f.gpu, f.camera, size, "abuffer").image;
        Image sorted = test::renderWith(*f.gpu, f.camera, size, "blend-sorted").image;
        Image unsorted = test::renderWith(*f.gpu, f.camera, size, "blend-unsorted").image;
        CHECK(compareImages(sorted, exact).maxAbsError <= kTolerance);
        if (n == 1) {
            CHECK(compareImages(unsorted, exact).maxAbsError <= kTolerance);
        } else {
            // Layers are submitted nearest first, the worst order for "over" blending.
            CHECK(compareImages(unsorted, exact).maxAbsError > 0.05);
        }
    }
}

TEST_CASE("two and three quads of known alpha composite to the closed form") {
    struct Layer { glm::vec3 color; float alpha; };
    const std::vector<std::vector<Layer>> cases = {
        {{{1, 0, 0}, 0.5f}, {{0, 0, 1}, 0.5f}},
        {{{0.2f, 0.9f, 0.3f}, 0.25f}, {{0.9f, 0.9f, 0.1f}, 0.75f}, {{0.1f, 0.2f, 0.8f}, 0.6f}},
    };
    for (const auto& layers : cases) {
        Scene s;
        s.materials.push_back(Material{});
        s.background = {0.1f, 0.2f, 0.3f};
        for (std::size_t i = 0; i < layers.size(); ++i) {
            Material m;
            m.unlit = true;  // the closed form needs no shading model: the colour is the base colour
            m.baseColor = layers[i].color;
            m.alpha = layers[i].alpha;
            m.alphaMode = AlphaMode::Blend;
            int mat = s.addMaterial(m);
            int mesh = s.addMesh(makeQuad(20, 20));
            Node node;
            node.local = glm::translate(glm::mat4(1.0f), {0, 0, -1.0f - float(i)});
            node.meshes = {mesh};
            node.materialOverride = mat;
            s.addNode(node);
        }
        s.camera = CameraPose{};
        Fixture f(s);
        // Closed form, back to front: c = a * layer + (1 - a) * c, starting from the background.
        glm::vec3 expected = s.background;
        for (auto it = layers.rbegin(); it != layers.rend(); ++it)
            expected = it->alpha * it->color + (1.0f - it->alpha) * expected;
        for (std::string id : {"abuffer", "blend-sorted"}) {
            CAPTURE(id);
            Image image = test::renderWith(*f.gpu, f.camera, {8, 8}, id).image;
            glm::vec4 centre = image.at(4, 4);
            CHECK(std::abs(centre.r - expected.r) <= kTolerance);
            CHECK(std::abs(centre.g - expected.g) <= kTolerance);
            CHECK(std::abs(centre.b - expected.b) <= kTolerance);
        }
    }
}

TEST_CASE("abuffer with a pool smaller than the fragments grows, re-renders and stays exact") {
    Fixture f(makeLayersScene(8));
    glm::ivec2 size(32, 24);
    auto roomy = test::renderWith(*f.gpu, f.camera, size, "abuffer");
    auto technique = createTechnique("abuffer");
    test::setSetting(*technique, "initial_nodes=100");
    auto tight = test::renderWith(*f.gpu, f.camera, size, *technique);
    CHECK(tight.result.stats.regrows >= 1);
    CHECK(tight.result.stats.fragmentsCaptured == 8u * 32u * 24u);
    CHECK(compareImages(tight.image, roomy.image).maxAbsError == 0.0);
    CHECK(tight.result.stats.bytes >= 8u * 32u * 24u * 24u);
}

TEST_CASE("abuffer renders in screen tiles when the fragments exceed the largest block") {
    Fixture f(makeLayersScene(16));
    glm::ivec2 size(64, 64);  // 65,536 fragments * 24 B = 1.5 MiB
    auto whole = test::renderWith(*f.gpu, f.camera, size, "abuffer");
    auto technique = createTechnique("abuffer");
    test::setSetting(*technique, "max_block_mib=0.25");
    auto tiled = test::renderWith(*f.gpu, f.camera, size, *technique);
    CHECK(tiled.result.stats.tiles >= 6);
    CHECK(tiled.result.stats.fragmentsCaptured == 16u * 64u * 64u);
    CHECK(compareImages(tiled.image, whole.image).maxAbsError <= 1e-6);
    // The next frame starts from these tiles: one store and one resolve each, no store wasted
    // on finding out again that larger tiles overflow. Each pixel holds the same set of
    // fragments, which the resolve's total order composites in one sequence whatever the tiles or
    // the order the nodes were appended in: equal to float round-off (bit-equal on llvmpipe; a GPU
    // need not rasterize a scissored tile bit for bit as the whole frame).
    auto again = test::renderWith(*f.gpu, f.camera, size, *technique);
    CHECK(again.result.stats.tiles == tiled.result.stats.tiles);
    CHECK(again.result.stats.passes == 2 * again.result.stats.tiles);
    CHECK(again.result.stats.regrows == 0);
    CHECK(compareImages(again.image, whole.image).maxAbsError <= 1e-6);
    CHECK(tiled.result.stats.passes > again.result.stats.passes);
    // With the fragments back within one pool, one tile again.
    test::setSetting(*technique, "max_block_mib=0");
    CHECK(test::renderWith(*f.gpu, f.camera, size, *technique).result.stats.tiles == 1);
}

TEST_CASE("abuffer's compute resolve gives the fragment resolve's image, whole and in tiles") {
    // Coincident shells (the tie rule), a long list (the selection walk) and tiles whose
    // sizes are not multiples of the 8x8 work groups.
    for (const std::string spec : {"shells:3:roundoff", "layers:70", "default"}) {
        CAPTURE(spec);
        Fixture f(makeBuiltinScene(spec));
        glm::ivec2 size(37, 29);
        auto fragment = test::renderWith(*f.gpu, f.camera, size, "abuffer");
        for (const std::string blockMiB : {"0", "0.05"}) {
            CAPTURE(blockMiB);
            auto technique = createTechnique("abuffer");
            test::setSetting(*technique, "compute_resolve=1");
            test::setSetting(*technique, std::string("max_block_mib=") + blockMiB);
            auto compute = test::renderWith(*f.gpu, f.camera, size, *technique);
            if (std::string(blockMiB) != "0" && std::string(spec) == "layers:70") CHECK(compute.result.stats.tiles > 1);
            // Two compiled stages may contract multiply-adds differently on a GPU: float
            // round-off, far below one 8-bit step, is all that may differ.
            CHECK(compareImages(compute.image, fragment.image).maxAbsError <= 1e-5);
            if (compareImages(compute.image, fragment.image).maxAbsError > 1e-5) {
                test::dumpImage(std::string("abuffer-compute-") + spec + "-" + blockMiB, compute.image);
                test::dumpImage(std::string("abuffer-fragment-") + spec, fragment.image);
            }
            CHECK(compute.result.stats.fragmentsCaptured == fragment.result.stats.fragmentsCaptured);
        }
    }
}

TEST_CASE("abuffer resolves lists longer than the register array exactly") {
    Fixture f(makeLayersScene(80));  // past LOCAL_CAPACITY = 64: the selection walk
    glm::ivec2 size(8, 8);
    auto gpu = test::renderWith(*f.gpu, f.camera, size, "abuffer");
    Image cpu = raycastReference(f.gpu->scene(), f.gpu->objects(), f.camera, size.x, size.y);
    CHECK(compareImages(gpu.image, cpu).maxAbsError <= kTolerance);
    CHECK(gpu.result.stats.fragmentsCaptured == 80u * 64u);
}

TEST_CASE("a scene with nothing transparent gets no transparency pass") {
    Scene s = makeCubesScene(false);
    for (auto& m : s.materials) m.alphaMode = AlphaMode::Opaque;
    Fixture f(s);
    auto r = test::renderWith(*f.gpu, f.camera, {16, 16}, "abuffer");
    CHECK_FALSE(r.result.transparencyPass);
    CHECK(r.result.stats.passes == 0);
    for (const auto& p : r.result.passTimes) CHECK(p.name == "opaque");
}
