// The coplanarity-aware peeling variants that store each layer's coincident fragments (f2b-ll,
// dual-ll, bun-ll: robust; f2b-fab, f2b-kb, dual-fab: K per pixel and layer) against the exact
// reference: every fragment captured and the reference's image where they promise it, exactly
// min(K, capacity) of K coincident copies where they do not, the rest counted; the same image
// whatever the submission order (up to float round-off); the list pool grown, or its overflow
// counted, never silent.
#include "gl_test_support.hpp"

#include "scene/builtin_scenes.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <map>
#include <string>
#include <vector>

using namespace strata;

namespace {

constexpr float kTolerance = 1.0f / 255.0f;
const std::vector<std::string> kRobust = {"f2b-ll", "dual-ll", "bun-ll"};
const std::vector<std::string> kBounded = {"f2b-fab", "f2b-kb", "dual-fab"};

std::vector<std::string> allVariants() {
    std::vector<std::string> ids = kRobust;
    ids.insert(ids.end(), kBounded.begin(), kBounded.end());
    return ids;
}

using test::Fixture;

// Renders `id` and checks it captured every fragment and equals `reference`.
void checkExact(const Fixture& f, glm::ivec2 size, const Image& reference, Technique& technique,
                FrameOptions options = {}) {
    auto r = test::renderWith(*f.gpu, f.camera, size, technique, options);
    REQUIRE(r.result.fragmentsTotal.has_value());
    CHECK(*r.result.fragmentsTotal > 0);
    CHECK(r.result.stats.fragmentsCaptured == *r.result.fragmentsTotal);
    CHECK(r.result.stats.fragmentsDropped == 0);
    CHECK_FALSE(r.result.stats.overflowed);
    CHECK(compareImages(r.image, reference).maxAbsError <= kTolerance);
}

}  // namespace

TEST_CASE("registry: the list variants are robust, the K-per-pixel ones bounded; all handle coplanarity") {
    for (const auto& id : kRobust) {
        CAPTURE(id);
        REQUIRE(findTechnique(id) != nullptr);
        CHECK(findTechnique(id)->info.robust);
        CHECK(findTechnique(id)->info.handlesCoplanarity);
    }
    for (const auto& id : kBounded) {
        CAPTURE(id);
        REQUIRE(findTechnique(id) != nullptr);
        CHECK_FALSE(findTechnique(id)->info.robust);
        CHECK(findTechnique(id)->info.handlesCoplanarity);
        CHECK(test::hasSetting(id, "capacity"));
    }
}

TEST_CASE("coplanar:K: the robust variants capture all K and equal the reference") {
    const glm::ivec2 size(16, 12);
    const std::uint64_t pixels = 16 * 12;
    for (int k : {1, 2, 3, 4, 5, 6, 7, 8, 9, 16}) {
        CAPTURE(k);
        Fixture f(makeBuiltinScene("coplanar:" + std::to_string(k)));
        Image reference = test::renderWith(*f.gpu, f.camera, size, "abuffer").image;
        for (const auto& id : kRobust) {
            CAPTURE(id);
            auto r = test::renderWith(*f.gpu, f.camera, size, id);
            REQUIRE(r.result.fragmentsTotal.has_value());
            CHECK(*r.result.fragmentsTotal == std::uint64_t(k) * pixels);
            CHECK(r.result.stats.fragmentsCaptured == std::uint64_t(k) * pixels);  // R_h = 1
            CHECK(r.result.stats.fragmentsDropped == 0);
            CHECK_FALSE(r.result.stats.overflowed);
            CHECK(compareImages(r.image, reference).maxAbsError <= kTolerance);
        }
        // One layer: f2b-ll anchors it, captures it once (depth + band + capture + resolve +
        // composite); dual-ll stores it on the front side (init + peel + resolve + composite);
        // bun-ll: range, store, resolve.
        // The pool (first one node a pixel) grows on the first frame to what the layer needs, a
        // repeated peel each: f2b-ll stores the K - 1 copies beside the anchor, dual-ll all K
        // (its first pool holds two a pixel: one per side).
        auto f2b = test::renderWith(*f.gpu, f.camera, size, "f2b-ll").result.stats;
        CHECK(f2b.passes == 5 + f2b.regrows);
        CHECK(f2b.regrows == (k > 2 ? 1 : 0));
        auto dual = test::renderWith(*f.gpu, f.camera, size, "dual-ll").result.stats;
        CHECK(dual.passes == 4 + dual.regrows);
        CHECK(dual.regrows == (k > 2 ? 1 : 0));  // its first pool: a node a pixel and side
        CHECK(test::renderWith(*f.gpu, f.camera, size, "bun-ll").result.stats.passes >= 3);
    }
}

TEST_CASE("coplanar:K: the bounded variants capture exactly min(K, capacity) a pixel and count the rest") {
    const glm::ivec2 size(16, 12);
    const std::uint64_t pixels = 16 * 12;
    for (int k : {1, 2, 3, 4, 5, 6, 7, 8, 9, 16}) {
        Fixture f(makeBuiltinScene("coplanar:" + std::to_string(k)));
        Image reference = test::renderWith(*f.gpu, f.camera, size, "abuffer").image;
        for (int capacity : {1, 3, 8}) {
            for (const auto& id : kBounded) {
                CAPTURE(k);
                CAPTURE(capacity);
                CAPTURE(id);
                auto t = test::makeTechnique(id, {"capacity=" + std::to_string(capacity)});
                auto r = test::renderWith(*f.gpu, f.camera, size, *t);
                const std::uint64_t kept = std::uint64_t(std::min(k, capacity));
                CHECK(r.result.stats.fragmentsCaptured == kept * pixels);  // R_h = min(K, capacity) / K
                CHECK(r.result.stats.fragmentsDropped == (std::uint64_t(k) - kept) * pixels);
                CHECK(r.result.stats.overflowed == (k > capacity));
                if (k <= capacity) CHECK(compareImages(r.image, reference).maxAbsError <= kTolerance);
                // The loss is visible while what lies behind the kept copies weighs (1 - 0.5)^K
                // of the pixel or more; behind 8 copies it is below 1/255.
                else if (capacity <= 3) CHECK(compareImages(r.image, reference).maxAbsError > 0.01);
            }
        }
    }
}

TEST_CASE("cubes, shells:3:roundoff and layers:N equal the reference, every fragment captured") {
    const glm::ivec2 size(48, 36);
    for (const std::string spec : {"cubes", "shells:3:roundoff", "layers:1", "layers:3", "layers:8"}) {
        CAPTURE(spec);
        Fixture f(makeBuiltinScene(spec));
        Image reference = test::renderWith(*f.gpu, f.camera, size, "abuffer").image;
        for (const auto& id : allVariants()) {
            CAPTURE(id);
            checkExact(f, size, reference, *test::makeTechnique(id));
        }
    }
}

TEST_CASE("layers:N costs a capture a layer (f2b), a peel per two layers (dual); bun-ll one store pass") {
    const glm::ivec2 size(20, 12);
    for (int n : {1, 2, 7, 16}) {
        CAPTURE(n);
        Fixture f(makeLayersScene(n, 0.3f));
        const int half = (n + 1) / 2;
        for (const std::string id : {"f2b-ll", "f2b-fab", "f2b-kb"}) {
            CAPTURE(id);
            auto s = test::renderWith(*f.gpu, f.camera, size, id).result.stats;
            // depth + n band edges + n captures + n resolves + n - 1 anchor passes + composite
            CHECK(s.passes == 4 * n + 1 + s.regrows);
            CHECK(s.fragmentsCaptured == std::uint64_t(n) * 240);
        }
        for (const std::string id : {"dual-ll", "dual-fab"}) {
            CAPTURE(id);
            auto s = test::renderWith(*f.gpu, f.camera, size, id).result.stats;
            CHECK(s.passes == 2 * half + 2 + s.regrows);  // init + peels + resolves + composite
            CHECK(s.fragmentsCaptured == std::uint64_t(n) * 240);
        }
        auto bun = test::renderWith(*f.gpu, f.camera, size, "bun-ll").result.stats;
        CHECK(bun.passes == 3 + bun.regrows);
        CHECK(bun.tiles == 1);
        CHECK(bun.fragmentsCaptured == std::uint64_t(n) * 240);
    }
}

TEST_CASE("reversed submission order changes nothing") {
    const glm::ivec2 size(48, 36);
    FrameOptions reversed;
    reversed.reverseSubmission = true;
    for (const std::string spec : {"coplanar:5", "cubes", "shells:3:roundoff"}) {
        CAPTURE(spec);
        Fixture f(makeBuiltinScene(spec));
        Image reference = test::renderWith(*f.gpu, f.camera, size, "abuffer").image;
        for (const auto& id : allVariants()) {
            CAPTURE(id);
            auto forward = test::renderWith(*f.gpu, f.camera, size, *test::makeTechnique(id));
            auto backward = test::renderWith(*f.gpu, f.camera, size, *test::makeTechnique(id), reversed);
            // A layer composites in scene order, whatever order its fragments arrived in. That
            // holds only while every fragment fits: a bounded variant keeps the first K to
            // arrive, and arrival order is the GPU's. So the premise is checked first. Not
            // bit-equal either: on a GPU another arrival order fills the pools in another order,
            // and nothing promises the same float rounding; 1e-6 is far below any misordering.
            REQUIRE(forward.result.stats.fragmentsDropped == 0);
            REQUIRE(backward.result.stats.fragmentsDropped == 0);
            CHECK(compareImages(forward.image, backward.image).maxAbsError <= 1e-6);
            CHECK(forward.result.stats.fragmentsCaptured == backward.result.stats.fragmentsCaptured);
            CHECK(compareImages(backward.image, reference).maxAbsError <= kTolerance);
        }
    }
}

TEST_CASE("a list pool that cannot grow keeps what fits and counts the rest; bun-ll tiles instead") {
    // coplanar:4 at 16x12 is one layer of 768 fragments; 0.01 MiB holds 436 nodes of 24 bytes,
    // fewer than the 576 f2b-ll stores beside its anchors.
    Fixture f(makeBuiltinScene("coplanar:4"));
    const glm::ivec2 size(16, 12);
    const std::uint64_t total = 4 * 192;
    const std::uint64_t fits = gl::storageBlockElements(24, 0.01);
    REQUIRE(fits < total);
    // dual-ll stores all four copies in the pool; f2b-ll keeps one a pixel as the anchor and
    // stores the other three.
    for (auto [id, kept] : {std::pair<std::string, std::uint64_t>{"dual-ll", fits}, {"f2b-ll", 192 + fits}}) {
        CAPTURE(id);
        auto r = test::renderWith(*f.gpu, f.camera, size, *test::makeTechnique(id, {"max_block_mib=0.01"}));
        CHECK(r.result.stats.overflowed);
        CHECK(r.result.stats.fragmentsCaptured == kept);
        CHECK(r.result.stats.fragmentsDropped == total - kept);
    }
    Image reference = test::renderWith(*f.gpu, f.camera, size, "abuffer").image;
    auto bun = test::renderWith(*f.gpu, f.camera, size, *test::makeTechnique("bun-ll", {"max_block_mib=0.01"}));
    CHECK(bun.result.stats.tiles >= 2);
    CHECK(bun.result.stats.fragmentsCaptured == total);
    CHECK_FALSE(bun.result.stats.overflowed);
    CHECK(compareImages(bun.image, reference).maxAbsError <= kTolerance);
}

TEST_CASE("bytes follow the formulas at precision 32") {
    Fixture f(makeLayersScene(3, 0.5f));
    const glm::ivec2 size(24, 10);
    const std::uint64_t pixels = 240;
    // Four depth buffers (4 B), two anchors (RGBA32UI, 16), an RGBA32F accumulation (16),
    // K - 1 entries of 20 B beside the anchor, the FAB counter (4),
    // two counters (8) and the total counter (4).
    const std::uint64_t f2bTargets = 16 + 32 + 16;
    CHECK(test::renderWith(*f.gpu, f.camera, size, *test::makeTechnique("f2b-fab", {"capacity=3", "precision=32"})).result.stats.bytes ==
          pixels * (f2bTargets + 2 * 20 + 4) + 8 + 4);
    CHECK(test::renderWith(*f.gpu, f.camera, size, *test::makeTechnique("f2b-kb", {"capacity=3", "precision=32"})).result.stats.bytes ==
          pixels * (f2bTargets + 2 * 20) + 8 + 4);
    // Two RG32F ranges and two RGBA32F accumulations (48), both sides' entries and counters.
    CHECK(test::renderWith(*f.gpu, f.camera, size, *test::makeTechnique("dual-fab", {"capacity=2", "precision=32"})).result.stats.bytes ==
          pixels * (48 + 2 * (2 * 20 + 4)) + 8);
    // f2b-ll: nothing coincides, so the pool keeps its first size, one node (24 B) a pixel, plus
    // heads.
    CHECK(test::renderWith(*f.gpu, f.camera, size, *test::makeTechnique("f2b-ll", {"precision=32"})).result.stats.bytes ==
          pixels * (f2bTargets + 24 + 4) + 8 + 4);
}

TEST_CASE("skipping peeled objects changes nothing on intersecting and coplanar scenes") {
    // f2b-*: the skip bound is the layer just peeled, which what is left lies behind by more
    // than the tie band; dual-*: dual's next range.
    const glm::ivec2 size(40, 30);
    std::map<std::string, std::uint64_t> skipped;
    for (const std::string spec : {"cubes", "cubes:separated", "volumes", "shells:3:roundoff", "default"}) {
        CAPTURE(spec);
        Fixture f(makeBuiltinScene(spec));
        for (const std::string id : {"f2b-ll", "f2b-fab", "dual-ll", "dual-fab"}) {
            CAPTURE(id);
            auto without = test::renderWith(*f.gpu, f.camera, size, *test::makeTechnique(id, {"skip_peeled=0"}));
            auto with = test::renderWith(*f.gpu, f.camera, size, *test::makeTechnique(id, {"skip_peeled=1"}));
            CHECK(without.result.stats.objectDrawsSkipped == 0);
            CHECK(compareImages(with.image, without.image).maxAbsError == 0.0);
            if (compareImages(with.image, without.image).maxAbsError != 0.0) {
                test::dumpImage(std::string("skip-with-") + id + "-" + spec, with.image);
                test::dumpImage(std::string("skip-without-") + id + "-" + spec, without.image);
            }
            CHECK(with.result.stats.fragmentsCaptured == without.result.stats.fragmentsCaptured);
            CHECK(with.result.stats.fragmentsDropped == without.result.stats.fragmentsDropped);
            skipped[id] += with.result.stats.objectDrawsSkipped;
        }
    }
    // The comparison means something only where draws were skipped.
    for (const auto& [id, n] : skipped) {
        CAPTURE(id);
        CHECK(n > 0);
    }
}
