// The coplanarity-aware peeling variants (f2b-2p, f2b-3p, dual-2p) against the exact reference:
// every fragment captured (R_h = 1) and the reference's image, whatever the coplanarity, the
// submission order or the depth complexity; plain f2b's R_h on K copies is 1/K (Table 1).
#include "gl_test_support.hpp"

#include "scene/builtin_scenes.hpp"

#include <doctest/doctest.h>

using namespace strata;

namespace {

constexpr float kTolerance = 1.0f / 255.0f;
const char* const kVariants[] = {"f2b-2p", "f2b-3p", "dual-2p"};

using test::Fixture;

// Renders `spec` with every variant, forward and reversed, and checks each against abuffer.
void checkAgainstReference(const std::string& spec, glm::ivec2 size) {
    CAPTURE(spec);
    Fixture f(makeBuiltinScene(spec));
    for (bool reversed : {false, true}) {
        CAPTURE(reversed);
        FrameOptions options;
        options.reverseSubmission = reversed;
        auto reference = test::renderWith(*f.gpu, f.camera, size, "abuffer", options);
        REQUIRE(reference.result.fragmentsTotal.has_value());
        const std::uint64_t total = *reference.result.fragmentsTotal;
        CHECK(total > 0);
        for (const char* id : kVariants) {
            CAPTURE(id);
            auto r = test::renderWith(*f.gpu, f.camera, size, id, options);
            CHECK(compareImages(r.image, reference.image).maxAbsError <= kTolerance);
            CHECK(r.result.stats.fragmentsCaptured == total);
            CHECK(r.result.stats.fragmentsDropped == 0);
            CHECK_FALSE(r.result.stats.overflowed);
        }
    }
}

}  // namespace

TEST_CASE("K coincident quads: every variant captures all K fragments in object order; f2b captures 1 of K") {
    for (int k : {1, 2, 3, 4, 5, 6, 7, 8, 9, 16}) {
        CAPTURE(k);
        Fixture f(makeCoplanarScene(k, 0.5f));
        glm::ivec2 size(12, 8);
        const std::uint64_t pixels = 96;
        // The exact colour: copies composite in object order, copy 0 in front.
        glm::vec3 expected = f.gpu->scene().background;
        for (int i = k - 1; i >= 0; --i)
            expected = 0.5f * test::litFacing(f.gpu->scene(), f.camera, size, 6, 4, paletteColor(i)) + 0.5f * expected;
        for (bool reversed : {false, true}) {
            CAPTURE(reversed);
            FrameOptions options;
            options.reverseSubmission = reversed;
            Image reference = test::renderWith(*f.gpu, f.camera, size, "abuffer", options).image;
            for (const char* id : kVariants) {
                CAPTURE(id);
                auto r = test::renderWith(*f.gpu, f.camera, size, id, options);
                REQUIRE(r.result.fragmentsTotal.has_value());
                CHECK(*r.result.fragmentsTotal == std::uint64_t(k) * pixels);
                CHECK(r.result.stats.fragmentsCaptured == std::uint64_t(k) * pixels);  // R_h = 1
                CHECK(r.result.stats.fragmentsDropped == 0);
                CHECK_FALSE(r.result.stats.overflowed);
                CHECK(compareImages(r.image, reference).maxAbsError <= kTolerance);
                glm::vec4 p = r.image.at(6, 4);
                CHECK(std::abs(p.r - expected.r) <= kTolerance);
                CHECK(std::abs(p.g - expected.g) <= kTolerance);
                CHECK(std::abs(p.b - expected.b) <= kTolerance);
            }
            auto base = test::renderWith(*f.gpu, f.camera, size, "f2b", options);
            CHECK(base.result.stats.fragmentsCaptured == pixels);  // R_h = 1/K
        }
    }
}

TEST_CASE("two fragments per iteration: f2b-2p peels K copies in ceil(K/2) iterations") {
    // f2b-2p: init + per iteration (count, resolve; an extraction and a second resolve where two
    // or more are left) + composite. K = 5: iterations with 5, 3, 1 left; the last extracts
    // nothing. So 2C passes a layer of C, the paper's 2C(Zall).
    Fixture f(makeCoplanarScene(5, 0.5f));
    auto r = test::renderWith(*f.gpu, f.camera, {8, 8}, "f2b-2p");
    CHECK(r.result.stats.passes == 1 + (4 + 4 + 2) + 1);
    // No coplanarity: D layers cost D iterations of count and resolve.
    Fixture layers(makeLayersScene(4, 0.3f));
    auto l = test::renderWith(*layers.gpu, layers.camera, {8, 8}, "f2b-2p");
    CHECK(l.result.stats.passes == 1 + 2 * 4 + 1);
    // f2b-3p: depth, band, count and resolve in the first iteration, and in the three after it
    // the same without the band (each resolve writes the next one); no shading pass where every
    // layer holds one fragment.
    auto l3 = test::renderWith(*layers.gpu, layers.camera, {8, 8}, "f2b-3p");
    CHECK(l3.result.stats.passes == 1 + 4 + 3 * 3 + 1);
    // K = 5 coplanar: the shading pass and a second resolve in the iterations with 5 and 3 left,
    // not with 1.
    auto r3 = test::renderWith(*f.gpu, f.camera, {8, 8}, "f2b-3p");
    CHECK(r3.result.stats.passes == 1 + (6 + 5 + 3) + 1);
}

TEST_CASE("z-fighting cubes, separated cubes and round-off shells equal the reference, forward and reversed") {
    checkAgainstReference("cubes", {48, 36});
    checkAgainstReference("cubes:separated", {48, 36});
    checkAgainstReference("shells:3:roundoff", {48, 36});
    checkAgainstReference("shells:3", {48, 36});
}

TEST_CASE("no coplanarity: N layers equal the reference") {
    for (int n : {1, 2, 7, 16}) checkAgainstReference("layers:" + std::to_string(n), {20, 12});
}

TEST_CASE("skipping peeled objects changes nothing on coplanar scenes") {
    for (const std::string spec : {"cubes", "coplanar:3", "default"}) {
        CAPTURE(spec);
        Fixture f(makeBuiltinScene(spec));
        glm::ivec2 size(40, 30);
        for (const char* id : kVariants) {
            CAPTURE(id);
            auto without = test::renderWith(*f.gpu, f.camera, size, *test::makeTechnique(id, {"skip_peeled=0"}));
            auto with = test::renderWith(*f.gpu, f.camera, size, *test::makeTechnique(id, {"skip_peeled=1"}));
            CHECK(compareImages(with.image, without.image).maxAbsError == 0.0);
            CHECK(with.result.stats.fragmentsCaptured == without.result.stats.fragmentsCaptured);
        }
    }
}

TEST_CASE("max_passes bounds the coplanar variants and reports what it left") {
    Fixture f(makeCoplanarScene(6, 0.5f));
    for (const char* id : kVariants) {
        CAPTURE(id);
        auto r = test::renderWith(*f.gpu, f.camera, {8, 8}, *test::makeTechnique(id, {"max_passes=1"}));
        CHECK(r.result.stats.overflowed);
        CHECK(r.result.stats.fragmentsCaptured + r.result.stats.fragmentsDropped == 6u * 64u);
        CHECK(r.result.stats.fragmentsDropped > 0);
    }
}
