// The buffer family (kbuffer, fab, ll, sbuffer) against the exact reference and closed forms:
// equal to abuffer when the capacity suffices, exactly K per pixel and the K nearest layers
// when it does not, the tail option, coplanar copies, the memory formulas and the S-buffer's
// prefix sum on awkward sizes.
#include "gl_test_support.hpp"

#include "oit/buffers/prefix_sum.hpp"
#include "reference/raycast.hpp"
#include "render/depth_order.hpp"
#include "scene/builtin_scenes.hpp"

#include <doctest/doctest.h>

#include <numeric>
#include <random>

using namespace strata;

namespace {

constexpr float kTolerance = 1.0f / 255.0f;

std::string capacity(int k) { return "capacity=" + std::to_string(k); }

struct Layers {
    GpuScene scene;
    Camera camera;
    Layers(int n, float alpha) : scene((test::glContext(), makeLayersScene(n, alpha))) {
        camera = defaultCamera(scene.scene(), scene.objects());
    }
};

// Pixels of `image` that equal, within kTolerance, the composite of some `k` (k < 0: any number)
// of the pixel's fragments (from the CPU ray cast) in depth order over the opaque colour; with
// `tailBehind`, followed by the remaining fragments as the tail layer composites them
// (buffers/tail_resolve.glsl: their alpha-weighted average colour at coverage 1 - prod(1 - a);
// for one overflowed fragment that is the fragment itself). Which fragments a bounded buffer
// keeps depends on the order they arrive in, which a GPU does not promise: every such subset
// is accepted.
std::uint64_t pixelsShowingKeptSubsets(const Layers& f, glm::ivec2 size, const Image& image, int k, bool tailBehind) {
    RaycastReference reference(f.scene.scene(), f.scene.objects());
    std::uint64_t matching = 0;
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) {
            PixelSample p = reference.samplePixel(f.camera, size.x, size.y, x, y);
            const int n = int(p.fragments.size());
            const glm::vec4 actual = image.at(x, y);
            bool found = false;
            for (unsigned mask = 0; mask < (1u << n) && !found; ++mask) {
                if (k >= 0 && __builtin_popcount(mask) != k) continue;
                std::vector<SurfaceFragment> ordered;
                for (int i = 0; i < n; ++i)
                    if (mask & (1u << i)) ordered.push_back(p.fragments[std::size_t(i)]);
                if (tailBehind && __builtin_popcount(mask) < n) {
                    SurfaceFragment tail;
                    glm::vec3 weighted(0.0f);
                    float alphaSum = 0.0f, reveal = 1.0f;
                    for (int i = 0; i < n; ++i) {
                        if (mask & (1u << i)) continue;
                        const SurfaceFragment& q = p.fragments[std::size_t(i)];
                        weighted += q.alpha * q.color;
                        alphaSum += q.alpha;
                        reveal *= 1.0f - q.alpha;
                    }
                    tail.alpha = 1.0f - reveal;
                    tail.color = alphaSum > 0.0f ? weighted / alphaSum : glm::vec3(0.0f);
                    ordered.push_back(tail);
                }
                glm::vec3 c = compositeOrdered(ordered, p.opaqueColor);
                found = std::abs(c.r - actual.r) <= kTolerance && std::abs(c.g - actual.g) <= kTolerance &&
                        std::abs(c.b - actual.b) <= kTolerance;
            }
            if (found) ++matching;
        }
    return matching;
}

}  // namespace

TEST_CASE("buffers with capacity >= N equal abuffer on N layers and capture every fragment") {
    // sbuffer sizes its storage from the count: robust. kbuffer, fab and ll hold a fixed capacity,
    // so at their defaults they drop what does not fit (not robust), but with K >= N they must
    // be exact too (they are also in the generic exact test).
    CHECK(findTechnique("sbuffer")->info.robust);
    CHECK_FALSE(findTechnique("fab")->info.robust);
    CHECK_FALSE(findTechnique("ll")->info.robust);
    CHECK_FALSE(findTechnique("kbuffer")->info.robust);
    for (int n : {1, 2, 7, 16, 33}) {
        Layers f(n, 0.3f);
        glm::ivec2 size(20, 12);
        const std::uint64_t total = std::uint64_t(n) * size.x * size.y;
        Image reference = test::renderWith(f.scene, f.camera, size, "abuffer").image;
        for (std::string id : {"kbuffer", "fab", "ll", "sbuffer"}) {
            CAPTURE(n);
            CAPTURE(id);
            auto t = id == "sbuffer" ? test::makeTechnique(id) : test::makeTechnique(id, {capacity(std::max(n, 1))});
            auto r = test::renderWith(f.scene, f.camera, size, *t);
            CHECK(compareImages(r.image, reference).maxAbsError <= kTolerance);
            REQUIRE(r.result.fragmentsTotal.has_value());
            CHECK(*r.result.fragmentsTotal == total);
            CHECK(r.result.stats.fragmentsCaptured == total);
            CHECK(r.result.stats.fragmentsDropped == 0);
            CHECK_FALSE(r.result.stats.overflowed);
        }
    }
}

TEST_CASE("kbuffer with K < N keeps the K nearest layers; fab keeps K of them, composited in order") {
    const int n = 7;
    const float alpha = 0.4f;
    glm::ivec2 size(16, 12);
    const std::uint64_t pixels = std::uint64_t(size.x) * size.y;
    Layers f(n, alpha);
    for (int k : {1, 3, 6}) {
        // The K nearest of N layers are the same objects (ids, materials, positions) as all the
        // layers of makeLayersScene(K): its exact image is the expected one.
        GpuScene nearest(makeLayersScene(k, alpha));
        Image expected = test::renderWith(nearest, f.camera, size, "abuffer").image;
        Image all = test::renderWith(f.scene, f.camera, size, "abuffer").image;
        REQUIRE(compareImages(expected, all).maxAbsError > 0.01);  // dropping layers is visible
        auto keep = test::renderWith(f.scene, f.camera, size, *test::makeTechnique("kbuffer", {capacity(k)}));
        REQUIRE(keep.result.fragmentsTotal.has_value());
        // kbuffer keeps the K nearest whatever the order they arrive in.
        FrameOptions reversed;
        reversed.reverseSubmission = true;
        auto kbReversed = test::renderWith(f.scene, f.camera, size, *test::makeTechnique("kbuffer", {capacity(k)}), reversed);
        CHECK(compareImages(keep.image, expected).maxAbsError <= kTolerance);
        CHECK(compareImages(kbReversed.image, expected).maxAbsError <= kTolerance);
        // fab keeps the first K to arrive, and a GPU's arrival order is not the submission order:
        // what is guaranteed is the count, and that each pixel shows the composite of some K of
        // its N fragments, in depth order.
        for (bool reverse : {false, true}) {
            auto fab = test::renderWith(f.scene, f.camera, size, *test::makeTechnique("fab", {capacity(k)}),
                                        reverse ? reversed : FrameOptions{});
            CAPTURE(k);
            CAPTURE(reverse);
            CHECK(fab.result.stats.fragmentsCaptured == k * pixels);
            CHECK(fab.result.stats.fragmentsDropped == (n - k) * pixels);
            CHECK(fab.result.stats.overflowed);
            CHECK(pixelsShowingKeptSubsets(f, size, fab.image, k, false) == pixels);
        }
        for (auto* r : {&keep, &kbReversed}) {
            CHECK(*r->result.fragmentsTotal == n * pixels);
            CHECK(r->result.stats.fragmentsCaptured == k * pixels);
            CHECK(r->result.stats.fragmentsDropped == (n - k) * pixels);
            CHECK(r->result.stats.fragmentsTail == 0);
            CHECK(r->result.stats.overflowed);
        }
    }
}

TEST_CASE("ll with a fixed pool smaller than the fragments counts the overflow and does not grow") {
    Layers f(7, 0.4f);
    glm::ivec2 size(16, 12);
    const std::uint64_t pixels = std::uint64_t(size.x) * size.y;
    auto r = test::renderWith(f.scene, f.camera, size, *test::makeTechnique("ll", {capacity(3)}));
    CHECK(r.result.stats.fragmentsCaptured == 3 * pixels);  // the pool: w*h*3 nodes
    CHECK(r.result.stats.fragmentsDropped == 4 * pixels);
    CHECK(r.result.stats.overflowed);
    CHECK(r.result.stats.regrows == 0);
    CHECK(r.result.stats.bytes == 3 * pixels * 24 + pixels * 4 + 16);
}

TEST_CASE("tail=1 blends what overflows: smaller error than dropping it, counted in fragmentsTail") {
    const int n = 7;
    Layers f(n, 0.4f);
    glm::ivec2 size(16, 12);
    const std::uint64_t pixels = std::uint64_t(size.x) * size.y;
    Image exact = test::renderWith(f.scene, f.camera, size, "abuffer").image;
    for (std::string id : {"kbuffer", "fab", "ll"}) {
        for (int k : {3, 6}) {
            CAPTURE(id);
            CAPTURE(k);
            auto dropped = test::renderWith(f.scene, f.camera, size, *test::makeTechnique(id, {capacity(k), "tail=0"}));
            auto tailed = test::renderWith(f.scene, f.camera, size, *test::makeTechnique(id, {capacity(k), "tail=1"}));
            double dropError = compareImages(dropped.image, exact).rmse;
            double tailError = compareImages(tailed.image, exact).rmse;
            CHECK(dropError > 0.002);  // one layer of 0.4 behind six: 0.6^6 of it shows
            // kbuffer keeps the k nearest whatever the arrival order, so its tail lies behind
            // them and can only help. fab and ll keep what arrived first: each pixel shows some
            // kept subset in depth order with the rest blended behind it (fab: k a pixel; ll's
            // pool is shared, so any number).
            if (id == "kbuffer") CHECK(tailError < dropError);
            else CHECK(pixelsShowingKeptSubsets(f, size, tailed.image, id == "fab" ? k : -1, true) == pixels);
            CHECK(tailed.result.stats.overflowed);
            CHECK(tailed.result.stats.fragmentsTail == (n - k) * pixels);
            CHECK(tailed.result.stats.fragmentsDropped == 0);
            CHECK(tailed.result.stats.fragmentsCaptured == k * pixels);
            if (k == n - 1) {
                // One overflowed fragment per pixel. kbuffer overflows the farthest, so its
                // tail is exact. fab overflows whichever arrived last: the image is the kept six
                // in depth order with that one behind them. (ll's pool is shared by all pixels,
                // so a pixel may overflow more than one.)
                if (id == "kbuffer") CHECK(compareImages(tailed.image, exact).maxAbsError <= kTolerance);
                if (id == "fab") CHECK(pixelsShowingKeptSubsets(f, size, tailed.image, k, true) == pixels);
            }
        }
    }
}

TEST_CASE("coplanar copies: ll and a large enough kbuffer or fab capture all K in object order") {
    test::glContext();
    for (int k : {2, 3, 5}) {
        GpuScene scene(makeCoplanarScene(k, 0.5f));
        Camera camera = defaultCamera(scene.scene(), scene.objects());
        glm::ivec2 size(8, 8);
        Image reference = test::renderWith(scene, camera, size, "abuffer").image;
        for (std::string id : {"ll", "kbuffer", "fab", "sbuffer"}) {
            CAPTURE(k);
            CAPTURE(id);
            FrameOptions reversed;
            reversed.reverseSubmission = true;
            for (bool reverse : {false, true}) {
                auto t = id == "sbuffer" ? test::makeTechnique(id) : test::makeTechnique(id, {capacity(k)});
                auto r = test::renderWith(scene, camera, size, *t, reverse ? reversed : FrameOptions{});
                CHECK(r.result.stats.fragmentsCaptured == std::uint64_t(k) * 64);
                CHECK(compareImages(r.image, reference).maxAbsError <= kTolerance);
            }
        }
        if (k > 2) {
            // Fewer kbuffer slots than coincident copies: exactly the slots are filled.
            auto r = test::renderWith(scene, camera, size, *test::makeTechnique("kbuffer", {capacity(2)}));
            CHECK(r.result.stats.fragmentsCaptured == 2u * 64u);
            CHECK(r.result.stats.fragmentsDropped == std::uint64_t(k - 2) * 64);
        }
    }
}

TEST_CASE("sbuffer stores and resolves in bands of rows when the fragments exceed the largest block") {
    Layers f(16, 0.3f);
    glm::ivec2 size(64, 48);  // 49,152 fragments * 20 B = 0.94 MiB
    const std::uint64_t total = 16u * 64u * 48u;
    auto whole = test::renderWith(f.scene, f.camera, size, "sbuffer");
    CHECK(whole.result.stats.tiles == 1);
    auto banded = test::renderWith(f.scene, f.camera, size, *test::makeTechnique("sbuffer", {"max_block_mib=0.2"}));
    // 0.2 MiB holds 10,485 entries: 10 rows of 1,024 per band, so 5 bands.
    CHECK(banded.result.stats.tiles == 5);
    CHECK(banded.result.stats.fragmentsCaptured == total);
    CHECK(banded.result.stats.fragmentsDropped == 0);
    CHECK_FALSE(banded.result.stats.overflowed);
    // Per pixel the same fragments, in the resolve's total order: equal to float round-off
    // (bit-equal on llvmpipe; a GPU need not rasterize each band bit for bit as the whole frame).
    CHECK(compareImages(banded.image, whole.image).maxAbsError <= 1e-6);
    // A block smaller than one row (1,024 entries): each row is a band of its own and keeps
    // what fits; the rest is counted as dropped, never written out of bounds.
    auto tiny = test::renderWith(f.scene, f.camera, size, *test::makeTechnique("sbuffer", {"max_block_mib=0.01"}));
    const std::uint64_t perRow = std::uint64_t(0.01 * 1024 * 1024) / 20;  // 524 entries
    CHECK(tiny.result.stats.tiles == 48);
    CHECK(tiny.result.stats.fragmentsCaptured == perRow * 48);
    CHECK(tiny.result.stats.fragmentsDropped == total - perRow * 48);
    CHECK(tiny.result.stats.overflowed);
}

TEST_CASE("buffer techniques report bytes by their formulas") {
    Layers f(7, 0.3f);
    glm::ivec2 size(20, 12);
    const std::uint64_t px = 20 * 12;
    const std::uint64_t tailBytes = px * 20;  // RGBA32F + R32F
    auto bytes = [&](const std::string& id, std::initializer_list<std::string> settings) {
        return test::renderWith(f.scene, f.camera, size, *test::makeTechnique(id, settings)).result.stats.bytes;
    };
    // fab: K entries of 20 B per pixel + a 4-byte counter per pixel + 16 B of stat counters.
    CHECK(bytes("fab", {capacity(8)}) == px * 8 * 20 + px * 4 + 16);
    CHECK(bytes("fab", {capacity(3), "tail=1"}) == px * 3 * 20 + px * 4 + 16 + tailBytes);
    // kbuffer: K slots of a 4-byte depth key and 20 B of attributes.
    CHECK(bytes("kbuffer", {capacity(8)}) == px * 8 * 24 + 16);
    CHECK(bytes("kbuffer", {capacity(2), "tail=1"}) == px * 2 * 24 + 16 + tailBytes);
    // ll: pool of w*h*capacity 24-byte nodes + heads + counter.
    CHECK(bytes("ll", {capacity(8)}) == px * 8 * 24 + px * 4 + 16);
    CHECK(bytes("ll", {capacity(4), "tail=1"}) == px * 4 * 24 + px * 4 + 16 + tailBytes);
    // sbuffer: offsets + exactly one 20-byte entry per fragment + the scan's block totals.
    CHECK(bytes("sbuffer", {}) == px * 4 + 7 * px * 20 + buffers::PrefixSum::scratchBytes(px) + 16);
    CHECK(buffers::PrefixSum::scratchBytes(px) == 4);
    CHECK(buffers::PrefixSum::scratchBytes(513) == 2 * 4 + 4);
    CHECK(buffers::PrefixSum::scratchBytes(512 * 512 + 1) == 513 * 4 + 2 * 4 + 4);
}

TEST_CASE("the GPU prefix sum is exact for any count") {
    test::glContext();
    buffers::PrefixSum scan;
    std::mt19937 rng(7);
    for (std::uint64_t n : {1ull, 2ull, 221ull /*17x13*/, 511ull, 512ull, 513ull, 2100ull /*300x7*/, 1024ull,
                            262145ull /*three levels*/}) {
        CAPTURE(n);
        std::vector<std::uint32_t> values(n);
        for (auto& v : values) v = rng() % 40;
        gl::Buffer buffer = gl::Buffer::create();
        glNamedBufferData(buffer.id(), GLsizeiptr(n * 4), values.data(), GL_DYNAMIC_COPY);
        std::uint32_t total = scan.scan(buffer.id(), n);
        std::vector<std::uint32_t> gpu(n);
        glGetNamedBufferSubData(buffer.id(), 0, GLsizeiptr(n * 4), gpu.data());
        gl::checkGl("prefix sum");
        std::vector<std::uint32_t> expected(n);
        std::exclusive_scan(values.begin(), values.end(), expected.begin(), 0u);
        CHECK(total == std::accumulate(values.begin(), values.end(), 0u));
        CHECK(gpu == expected);
    }
}

TEST_CASE("sbuffer is exact on awkward viewport sizes (1x1, 17x13, 300x7)") {
    Layers f(5, 0.35f);
    for (glm::ivec2 size : {glm::ivec2(1, 1), glm::ivec2(17, 13), glm::ivec2(300, 7)}) {
        CAPTURE(size.x);
        CAPTURE(size.y);
        Image reference = test::renderWith(f.scene, f.camera, size, "abuffer").image;
        auto r = test::renderWith(f.scene, f.camera, size, "sbuffer");
        CHECK(compareImages(r.image, reference).maxAbsError <= kTolerance);
        // At 300x7 (43:1) the outer layers no longer cover the view: compare with the shared count.
        REQUIRE(r.result.fragmentsTotal.has_value());
        CHECK(*r.result.fragmentsTotal > 0);
        CHECK(r.result.stats.fragmentsCaptured == *r.result.fragmentsTotal);
        CHECK_FALSE(r.result.stats.overflowed);
    }
}
