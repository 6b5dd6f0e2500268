// Accumulation precision: the `precision` parameter (16 or 32 bits per channel) of every
// technique that blends into, or stores colour in, float targets of its own. Both settings are
// held to stated tolerances against the exact reference on builtin layers scenes, the memory
// follows each setting's formula, wboit's half-float weights stay finite where unscaled ones
// overflow, and the floor counts exactly N*w*h fragments and leaves the opaque image.
#include "gl_test_support.hpp"

#include "bench/bench.hpp"
#include "scene/builtin_scenes.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace strata;

namespace {

// Exact techniques at half float: within 2/255 of the reference (measured at 32x32: up to
// 2.8e-3 for f2b and f2b2 on 16 layers of alpha 0.4, 2.4e-3 dual, 8.5e-4 blend-sorted).
constexpr float kHalfTolerance = 2.0f / 255.0f;
// At float: limited by the reference itself, which stores fragment colours as half floats
// (abuffer's 24-byte node), so 1e-4-level differences remain (measured up to 1.3e-4).
constexpr float kFloatTolerance = 2.5e-4f;

using test::Fixture;

bool hasPrecision(Technique& t) { return test::hasSetting(t.info().id, "precision"); }

bool allFinite(const Image& image) {
    for (float v : image.rgba)
        if (!std::isfinite(v)) return false;
    return true;
}

}  // namespace

TEST_CASE("precision is offered by every technique with float targets of its own, and is 16 or 32") {
    const std::vector<std::string> with = {"blend-unsorted", "blend-sorted", "f2b", "f2b2", "dual", "bun",
                                           "wboit", "stochastic", "kbuffer", "fab", "ll"};
    for (const auto& id : with) {
        CAPTURE(id);
        auto t = createTechnique(id);
        REQUIRE(hasPrecision(*t));
        CHECK_NOTHROW(test::setSetting(*t, "precision=16"));
        CHECK_NOTHROW(test::setSetting(*t, "precision=32"));
        for (const char* bad : {"precision=24", "precision=8", "precision=64", "precision=17"})
            CHECK_THROWS_AS(test::setSetting(*t, bad), std::invalid_argument);
    }
    for (const std::string id : {"abuffer", "sbuffer", "floor"}) {
        CAPTURE(id);
        auto t = createTechnique(id);
        CHECK_FALSE(hasPrecision(*t));
    }
}

TEST_CASE("exact techniques match the reference at both precisions on layers scenes") {
    struct Case {
        std::string id;
        std::vector<std::string> settings;
        std::vector<int> layers;
    };
    // kbuffer keeps the n - 1 nearest and blends the farthest into the tail, which is exact for
    // one fragment: the tail's precision is all that differs. fab and ll keep what arrives
    // first, so with n - 1 places the fragment in the tail is whichever came last, which on a
    // GPU is not always the farthest (an H100 put a middle layer there: 0.046 off on 4 layers).
    // They get n places: their stored colours are abuffer's half floats (measured equal), their
    // precision setting is the tail's alone, the tail code kbuffer's case measures, and the
    // tail's arrival-order behaviour is buffers_gl_test's.
    const std::vector<Case> cases = {
        {"blend-sorted", {}, {4, 16}},
        {"f2b", {}, {4, 16}},
        {"f2b2", {}, {4, 16}},
        {"dual", {}, {4, 16}},
        {"bun", {}, {4, 8}},  // 8 buckets of two: exact while no bucket holds three
        {"kbuffer", {"tail=1"}, {4, 16}},
        {"fab", {}, {4, 16}},
        {"ll", {}, {4, 16}},
    };
    glm::ivec2 size(32, 32);
    for (int n : {4, 8, 16}) {
        Fixture f(makeLayersScene(n, 0.4f));
        Image reference = test::renderWith(*f.gpu, f.camera, size, "abuffer").image;
        for (const auto& c : cases) {
            if (std::find(c.layers.begin(), c.layers.end(), n) == c.layers.end()) continue;
            std::vector<std::string> settings = c.settings;
            if (c.id == "kbuffer") settings.push_back("capacity=" + std::to_string(n - 1));
            if (c.id == "fab" || c.id == "ll") settings.push_back("capacity=" + std::to_string(n));
            float error[2] = {0, 0};
            for (int bits : {16, 32}) {
                CAPTURE(c.id);
                CAPTURE(n);
                CAPTURE(bits);
                settings.push_back("precision=" + std::to_string(bits));
                auto r = test::renderWith(*f.gpu, f.camera, size, *test::makeTechnique(c.id, settings));
                settings.pop_back();
                float e = compareImages(r.image, reference).maxAbsError;
                error[bits == 32] = e;
                CHECK(e <= (bits == 16 ? kHalfTolerance : kFloatTolerance));
                CHECK(r.result.stats.fragmentsDropped == 0);
            }
            MESSAGE(c.id << " on " << n << " layers: max error " << error[0] << " at precision=16, " << error[1]
                         << " at 32");
        }
    }
}

TEST_CASE("approximate techniques: half and float accumulation give the same picture") {
    // Their error is the approximation's; precision must not add to it visibly.
    glm::ivec2 size(32, 32);
    for (int n : {4, 16}) {
        Fixture f(makeLayersScene(n, 0.4f));
        Image reference = test::renderWith(*f.gpu, f.camera, size, "abuffer").image;
        for (std::string id : {"blend-unsorted", "wboit", "stochastic"}) {
            CAPTURE(id);
            CAPTURE(n);
            auto half = test::renderWith(*f.gpu, f.camera, size, *test::makeTechnique(id, {"precision=16"}));
            auto full = test::renderWith(*f.gpu, f.camera, size, *test::makeTechnique(id, {"precision=32"}));
            CHECK(allFinite(half.image));
            float between = compareImages(half.image, full.image).maxAbsError;
            double rmse16 = compareImages(half.image, reference).rmse;
            double rmse32 = compareImages(full.image, reference).rmse;
            CHECK(between <= kHalfTolerance);
            CHECK(std::abs(rmse16 - rmse32) <= 1e-3);
            MESSAGE(id << " on " << n << " layers: half vs float max " << between << ", rmse " << rmse16 << " / "
                       << rmse32);
        }
    }
}

TEST_CASE("memory follows the precision: RGBA16F 8 B, RGBA32F 16 B, R16F 2 B, R32F 4 B per pixel") {
    Fixture f(makeLayersScene(3, 0.5f));
    glm::ivec2 size(24, 10);
    const std::uint64_t px = 240;
    auto bytes = [&](const char* id, std::vector<std::string> settings) {
        return test::renderWith(*f.gpu, f.camera, size, *test::makeTechnique(id, settings)).result.stats.bytes;
    };
    CHECK(bytes("blend-unsorted", {"precision=16"}) == px * 8);  // RGBA16F scratch
    CHECK(bytes("blend-unsorted", {"precision=32"}) == 0);       // blends into the output
    CHECK(bytes("blend-sorted", {"precision=16"}) == px * 8);
    CHECK(bytes("blend-sorted", {"precision=32"}) == 0);
    CHECK(bytes("f2b", {"precision=16"}) == px * (2 * 4 + 2 * 8));
    CHECK(bytes("f2b", {"precision=32"}) == px * (2 * 4 + 2 * 16));
    CHECK(bytes("f2b2", {"precision=16"}) == px * (2 * 8 + 8));
    CHECK(bytes("f2b2", {"precision=32"}) == px * (2 * 8 + 16));
    // dual: + the back depth buffer (back_depth_test, 4 B).
    CHECK(bytes("dual", {"precision=16"}) == px * (2 * 8 + 4 * 8 + 4));
    CHECK(bytes("dual", {"precision=32"}) == px * (2 * 8 + 4 * 16 + 4));
    CHECK(bytes("bun", {"precision=16"}) == px * (8 + 4 * 16 + 8 * 2 * 8) + 8);
    CHECK(bytes("bun", {"precision=32"}) == px * (8 + 4 * 16 + 8 * 2 * 16) + 8);
    CHECK(bytes("wboit", {"precision=16"}) == px * 10);
    CHECK(bytes("wboit", {"precision=32"}) == px * 20);
    CHECK(bytes("stochastic", {"precision=16"}) == px * (8 * 4 + 10));
    CHECK(bytes("stochastic", {"precision=32"}) == px * (8 * 4 + 20));
    CHECK(bytes("fab", {"capacity=3", "tail=1", "precision=16"}) == px * 3 * 20 + px * 4 + 16 + px * 10);
    CHECK(bytes("fab", {"capacity=3", "tail=1", "precision=32"}) == px * 3 * 20 + px * 4 + 16 + px * 20);
    CHECK(bytes("fab", {"capacity=3", "tail=0", "precision=16"}) == px * 3 * 20 + px * 4 + 16);
    CHECK(bytes("kbuffer", {"capacity=2", "tail=1", "precision=16"}) == px * 2 * 24 + 16 + px * 10);
    CHECK(bytes("ll", {"capacity=4", "tail=1", "precision=16"}) == px * 4 * 24 + px * 4 + 16 + px * 10);
    CHECK(bytes("floor", {}) == px);  // its R8 scratch target
}

TEST_CASE("wboit at half float: weights scaled so 64 near fragments at the weight clamp stay in range") {
    // 64 coincident quads of alpha 0.9 at eye distance 0.1: equation 7's weight is at its clamp
    // (3e3), so each fragment adds 0.81 * 3e3 to the accumulated alpha (155520 in all) and about
    // half that to each colour channel, past half float's 65504. Unscaled, RGBA16F goes to
    // infinity on GPUs and saturates at 65504 on llvmpipe; scaled by 1/16, every sum fits. The
    // picture is about 1.7 bright (the paper's composite caps the alpha sum at 5e4): half float's
    // rounding over 64 additions leaves ~1% of it (0.017), unscaled saturation 24% (0.42).
    Scene s = makeCoplanarScene(64, 0.9f);
    test::glContext();
    GpuScene gpu(std::move(s));
    Camera camera = defaultCamera(gpu.scene(), gpu.objects());
    camera.position = {0, 0, -1.9f};
    camera.orientation = glm::quat(1, 0, 0, 0);
    camera.fitClipPlanes(gpu.bounds());
    glm::ivec2 size(16, 16);
    auto half = test::renderWith(gpu, camera, size, *test::makeTechnique("wboit", {"precision=16"}));
    auto full = test::renderWith(gpu, camera, size, *test::makeTechnique("wboit", {"precision=32"}));
    CHECK(allFinite(full.image));
    CHECK(allFinite(half.image));
    CHECK(compareImages(half.image, full.image).maxAbsError <= 0.03f);
}

TEST_CASE("floor: exactly N*w*h fragments on builtin layers, the opaque image, one pass") {
    for (int n : {1, 4, 16}) {
        CAPTURE(n);
        Fixture f(makeLayersScene(n, 0.5f));
        glm::ivec2 size(32, 24);
        auto r = test::renderWith(*f.gpu, f.camera, size, "floor");
        CHECK(r.result.stats.fragmentsCaptured == std::uint64_t(n) * size.x * size.y);
        REQUIRE(r.result.fragmentsTotal.has_value());
        CHECK(r.result.stats.fragmentsCaptured == *r.result.fragmentsTotal);
        CHECK(r.result.stats.passes == 1);
        glm::vec3 background = f.gpu->scene().background;
        float worst = 0.0f;
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x)
                for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(r.image.at(x, y)[c] - background[c]));
        CHECK(worst == 0.0f);
    }
}
