// Properties every exact (robust) technique in the registry must have, checked against the
// reference: it reproduces abuffer on exactly-N-layer scenes, captures every fragment, and does
// not depend on the order objects are submitted in.
#include "gl_test_support.hpp"

#include "reference/raycast.hpp"
#include "render/depth_order.hpp"
#include "scene/builtin_scenes.hpp"

#include <doctest/doctest.h>

#include <algorithm>

using namespace strata;

namespace {

constexpr float kTolerance = 1.0f / 255.0f;

// A technique with a bounded capacity gets enough of it for `layers` fragments per pixel.
std::unique_ptr<Technique> exactTechnique(const std::string& id, int layers) {
    auto t = createTechnique(id);
    if (test::hasSetting(id, "capacity")) test::setSetting(*t, "capacity=" + std::to_string(std::max(layers, 1)));
    return t;
}

// The techniques that are exact given enough memory: the robust ones, and the bounded ones
// (a `capacity` setting) given a capacity that holds every fragment.
std::vector<std::string> robustIds() {
    std::vector<std::string> ids;
    for (const auto& e : techniqueRegistry()) {
        if (e.info.robust || test::hasSetting(e.info.id, "capacity")) ids.push_back(e.info.id);
    }
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
    for (const std::string spec : {"layers:5", "cubes:separated", "volumes", "cubes", "default", "coplanar:3", "shells:3",
                             "shells:3:roundoff"}) {
        const std::string name(spec);
        bool coplanar = name == "cubes" || name == "default" || name.rfind("coplanar", 0) == 0 ||
                        name.rfind("shells", 0) == 0;
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
            if (compareImages(forward, backward).maxAbsError > kTolerance) {
                test::dumpImage("reversed-forward-" + id + "-" + name, forward);
                test::dumpImage("reversed-backward-" + id + "-" + name, backward);
            }
        }
        if (std::string(spec) == "layers:5") {
            Image forward = test::renderWith(scene, camera, size, "blend-unsorted").image;
            Image backward = test::renderWith(scene, camera, size, "blend-unsorted", reversed).image;
            CHECK(compareImages(forward, backward).maxAbsError > 0.05);
        }
    }
}

TEST_CASE("coincident surfaces and the same surfaces off by round-off render alike (the tie rule)") {
    test::glContext();
    // builtin:shells:3:roundoff places copies 1 and 2 through other transforms and scales them
    // by one and two ulps: the depths differ by round-off at most pixels. Under the tie rule
    // both scenes are three layers of coincident fragments in object order, so every exact
    // technique that handles coplanarity gives the exact scene's image.
    GpuScene exact(makeBuiltinScene("shells:3"));
    GpuScene roundoff(makeBuiltinScene("shells:3:roundoff"));
    Camera camera = defaultCamera(exact.scene(), exact.objects());
    glm::ivec2 size(40, 30);
    // Also at a near/far ratio of 1e8: the rule compares w = d + n / (f - n), which keeps its
    // relative precision where the window depth itself is tiny.
    Camera wide = camera;
    wide.nearPlane = 1e-4f;
    wide.farPlane = 1e4f;
    for (const Camera& c : {camera, wide}) {
        CAPTURE(c.farPlane / c.nearPlane);
        for (const auto& id : robustIds()) {
            if (!findTechnique(id)->info.handlesCoplanarity) continue;
            CAPTURE(id);
            auto a = test::renderWith(exact, c, size, *exactTechnique(id, 8));
            auto b = test::renderWith(roundoff, c, size, *exactTechnique(id, 8));
            CHECK(compareImages(a.image, b.image).maxAbsError <= kTolerance);
            CHECK(a.result.stats.fragmentsCaptured == *a.result.fragmentsTotal);
        }
    }
    // The CPU ray cast follows the same rule.
    Image cpuExact = raycastReference(exact.scene(), exact.objects(), camera, size.x, size.y);
    Image cpuRoundoff = raycastReference(roundoff.scene(), roundoff.objects(), camera, size.x, size.y);
    CHECK(compareImages(cpuExact, cpuRoundoff).maxAbsError <= kTolerance);

    // Without the tolerance (ties only on bit-equal depths) round-off decides the order, and
    // the images differ: the test above can fail.
    Scene strictScene = makeBuiltinScene("shells:3:roundoff");
    strictScene.depthTieUlps = 0.0;
    GpuScene strict(std::move(strictScene));
    Image exactImage = test::renderWith(exact, camera, size, "abuffer").image;
    Image strictImage = test::renderWith(strict, camera, size, "abuffer").image;
    CHECK(compareImages(exactImage, strictImage).maxAbsError > 0.02);
}

TEST_CASE("surfaces farther apart than the tie tolerance composite by depth, on the GPU as on the CPU") {
    test::glContext();
    // Two full-view quads; object 0 is behind object 1 by a relative gap of 8 tie tolerances
    // (at the default 1024 ulps 9.8e-4: two surfaces; also at another default,
    // STRATA_DEBUG_DEPTH_TIE_ULPS) or 2.4e-7 (2 ulps: one layer, object 0 first).
    const double tolerance = tieToleranceFromUlps(makeCoplanarScene(2, 0.5f).depthTieUlps);
    for (double gap : {8.0 * tolerance, 2.4e-7}) {
        CAPTURE(gap);
        Scene s = makeCoplanarScene(2, 0.5f);
        s.nodes[std::size_t(s.roots[0])].local[3].z = float(-2.0 * (1.0 + gap));
        GpuScene scene(std::move(s));
        Camera camera = defaultCamera(scene.scene(), scene.objects());
        auto gpu = test::renderWith(scene, camera, {8, 8}, "abuffer").image.at(4, 4);
        auto cpu = raycastReference(scene.scene(), scene.objects(), camera, 8, 8).at(4, 4);
        // The nearer colour dominates with weight 0.5 against 0.25.
        glm::vec3 bg = scene.scene().background;
        glm::vec3 c0 = test::litFacing(scene.scene(), camera, {8, 8}, 4, 4, paletteColor(0));
        glm::vec3 c1 = test::litFacing(scene.scene(), camera, {8, 8}, 4, 4, paletteColor(1));
        glm::vec3 front = gap > tolerance ? c1 : c0, back = gap > tolerance ? c0 : c1;
        glm::vec3 expected = 0.5f * front + 0.25f * back + 0.25f * bg;
        for (int ch = 0; ch < 3; ++ch) {
            CHECK(std::abs(gpu[ch] - expected[ch]) <= kTolerance);
            CHECK(std::abs(cpu[ch] - expected[ch]) <= kTolerance);
        }
    }
}

TEST_CASE("coplanar copies: abuffer captures all K and orders them by object id") {
    test::glContext();
    // 70 copies: more than the resolve's 64 registers, so one layer of ties goes through the
    // selection walk (the first copies dominate the colour, so a wrong order shows).
    for (int k : {2, 3, 5, 70}) {
        CAPTURE(k);
        GpuScene scene(makeCoplanarScene(k, 0.5f));
        Camera camera = defaultCamera(scene.scene(), scene.objects());
        auto r = test::renderWith(scene, camera, {8, 8}, "abuffer");
        CHECK(r.result.stats.fragmentsCaptured == std::uint64_t(k) * 64);
        // Ties go to the lower object id first: copy 0 is the front-most.
        glm::vec3 expected = scene.scene().background;
        for (int i = k - 1; i >= 0; --i)
            expected = 0.5f * test::litFacing(scene.scene(), camera, {8, 8}, 4, 4, paletteColor(i)) + 0.5f * expected;
        glm::vec4 p = r.image.at(4, 4);
        CHECK(std::abs(p.r - expected.r) <= kTolerance);
        CHECK(std::abs(p.g - expected.g) <= kTolerance);
        CHECK(std::abs(p.b - expected.b) <= kTolerance);
    }
}
