// Properties every exact (robust) technique in the registry must have, checked against the
// reference: it reproduces abuffer on exactly-N-layer scenes, captures every fragment, and does
// not depend on the order objects are submitted in.
#include "gl_test_support.hpp"

#include "scene/builtin_scenes.hpp"

#include <doctest/doctest.h>

using namespace strata;

namespace {

constexpr float kTolerance = 1.0f / 255.0f;

// A robust technique with a bounded capacity gets enough of it for `layers` fragments per pixel.
std::unique_ptr<Technique> exactTechnique(const std::string& id, int layers) {
    auto t = createTechnique(id);
    for (const auto& p : t->parameters())
        if (p.name == "capacity") setParameter(*t, "capacity=" + std::to_string(std::max<double>(layers, p.min)));
    return t;
}

std::vector<std::string> robustIds() {
    std::vector<std::string> ids;
    for (const auto& e : techniqueRegistry())
        if (e.info.robust) ids.push_back(e.info.id);
    return ids;
}

}  // namespace

TEST_CASE("exact techniques equal abuffer on N layers and capture every fragment") {
    test::glContext();
    REQUIRE_FALSE(robustIds().empty());
    for (int n : {1, 2, 7, 16, 33}) {
        GpuScene scene(makeLayersScene(n, 0.3f));
        Camera camera = defaultCamera(scene.scene(), scene.objects());
        glm::ivec2 size(20, 12);
        Image reference = test::renderWith(scene, camera, size, "abuffer").image;
        for (const auto& id : robustIds()) {
            CAPTURE(n);
            CAPTURE(id);
            auto technique = exactTechnique(id, n);
            auto r = test::renderWith(scene, camera, size, *technique);
            CHECK(compareImages(r.image, reference).maxAbsError <= kTolerance);
            REQUIRE(r.result.fragmentsTotal.has_value());
            CHECK(*r.result.fragmentsTotal == std::uint64_t(n) * size.x * size.y);
            CHECK(r.result.stats.fragmentsCaptured == *r.result.fragmentsTotal);
            CHECK_FALSE(r.result.stats.overflowed);
        }
    }
}

TEST_CASE("reversing the submission order leaves exact techniques unchanged and changes blend-unsorted") {
    test::glContext();
    // Without coincident surfaces every robust technique is order-independent; with them, only
    // those that break depth ties by (object id, primitive id) are.
    for (const char* spec : {"layers:5", "cubes:separated", "volumes", "cubes", "default"}) {
        bool coplanar = std::string(spec) == "cubes" || std::string(spec) == "default";
        CAPTURE(spec);
        GpuScene scene(makeBuiltinScene(spec));
        Camera camera = defaultCamera(scene.scene(), scene.objects());
        glm::ivec2 size(40, 30);
        FrameOptions reversed;
        reversed.reverseSubmission = true;
        for (const auto& id : robustIds()) {
            if (coplanar && !findTechnique(id)->info.handlesCoplanarity) continue;
            CAPTURE(id);
            Image forward = test::renderWith(scene, camera, size, *exactTechnique(id, 64)).image;
            Image backward = test::renderWith(scene, camera, size, *exactTechnique(id, 64), reversed).image;
            CHECK(compareImages(forward, backward).maxAbsError <= kTolerance);
        }
        if (std::string(spec) == "layers:5") {
            Image forward = test::renderWith(scene, camera, size, "blend-unsorted").image;
            Image backward = test::renderWith(scene, camera, size, "blend-unsorted", reversed).image;
            CHECK(compareImages(forward, backward).maxAbsError > 0.05);
        }
    }
}

TEST_CASE("coplanar copies: abuffer captures all K and orders them by object id") {
    test::glContext();
    for (int k : {2, 3, 5}) {
        CAPTURE(k);
        GpuScene scene(makeCoplanarScene(k, 0.5f));
        Camera camera = defaultCamera(scene.scene(), scene.objects());
        auto r = test::renderWith(scene, camera, {8, 8}, "abuffer");
        CHECK(r.result.stats.fragmentsCaptured == std::uint64_t(k) * 64);
        // Ties go to the lower object id first: copy 0 is the front-most.
        glm::vec3 expected = scene.scene().background;
        for (int i = k - 1; i >= 0; --i) expected = 0.5f * paletteColor(i) + 0.5f * expected;
        glm::vec4 p = r.image.at(4, 4);
        CHECK(std::abs(p.r - expected.r) <= kTolerance);
        CHECK(std::abs(p.g - expected.g) <= kTolerance);
        CHECK(std::abs(p.b - expected.b) <= kTolerance);
    }
}
