// The GPU coplanarity detector (oit/coplanarity_detector.hpp) against the CPU ray cast: the same
// largest depth layer per pixel on every builtin scene, Fig. 13's colours, C_p, and the detector's
// independence of tiles and submission order.
#include "gl_test_support.hpp"

#include "reference/raycast.hpp"
#include "render/coplanarity.hpp"
#include "render/depth_order.hpp"
#include "scene/builtin_scenes.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>

using namespace strata;

namespace {

struct Detected {
    FrameResult result;
    CoplanarityDetector::Pixels pixels;
    Image heatmap;
};

Detected detect(const GpuScene& scene, const Camera& camera, glm::ivec2 size, FrameOptions options = {}) {
    test::glContext();
    FrameRenderer renderer;
    options.detectCoplanarity = true;
    options.countFragments = true;
    Detected d;
    // No technique: the detector needs only the opaque pass before it.
    d.result = renderer.render(scene, camera, size, nullptr, options);
    gl::checkGl("detect");
    REQUIRE(renderer.coplanarity() != nullptr);
    d.pixels = renderer.coplanarity()->readPixels();
    d.heatmap = renderer.coplanarity()->readHeatmap();
    gl::checkGl("read back");
    return d;
}

// The CPU side: each pixel's ray-cast fragments reduced by the same rule.
struct CpuPixels {
    std::vector<int> largestLayer, fragments;
    // Pixels where two consecutive ray-cast depths lie between a quarter of the tie tolerance
    // and four times it. Where surfaces intersect, their gap passes through every value, so at
    // any tolerance some pixel centres fall near the cut, and there a GPU's round-off (up to
    // ~1024 ulps on NVIDIA) decides the side: those pixels cannot be held to the ray cast.
    // Coincident surfaces (a gap of a few ulps) and distinct ones are never in this band.
    std::vector<bool> nearTheCut;
};

bool gapNearTheCut(std::vector<float> depths, double tolerance) {
    std::sort(depths.begin(), depths.end());
    for (std::size_t i = 1; i < depths.size(); ++i) {
        const double gap = (double(depths[i]) - double(depths[i - 1])) / double(depths[i]);
        if (gap > 0.25 * tolerance && gap < 4.0 * tolerance) return true;
    }
    return false;
}

CpuPixels raycastLargestLayers(const GpuScene& scene, const Camera& camera, glm::ivec2 size) {
    RaycastReference reference(scene.scene(), scene.objects());
    const double tolerance = tieToleranceFromUlps(scene.scene().depthTieUlps);
    CpuPixels out;
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) {
            PixelSample p = reference.samplePixel(camera, size.x, size.y, x, y);
            std::vector<float> depths;
            for (const auto& f : p.fragments) depths.push_back(f.depth);
            out.largestLayer.push_back(largestDepthLayer(depths, tolerance));
            out.fragments.push_back(int(p.fragments.size()));
            out.nearTheCut.push_back(gapNearTheCut(depths, tolerance));
        }
    return out;
}

// 8-bit sRGB of a linear value, as a PNG stores it.
int srgbByte(float linear) { return int(std::lround(linearToSrgb(std::clamp(linear, 0.0f, 1.0f)) * 255.0f)); }

}  // namespace

TEST_CASE("coplanarity detector equals the CPU ray cast on every builtin scene") {
    const std::vector<std::string> specs = {"layers:1", "layers:4", "coplanar:1", "coplanar:2", "coplanar:3",
                                            "coplanar:4", "coplanar:5", "coplanar:6", "coplanar:7", "coplanar:8",
                                            "coplanar:9", "coplanar:16", "shells:3", "shells:3:roundoff", "cubes",
                                            "cubes:separated", "volumes", "slabs:3", "default"};
    const glm::ivec2 size(48, 36);
    const int pixels = size.x * size.y;
    for (const auto& spec : specs) {
        CAPTURE(spec);
        test::Fixture f(makeBuiltinScene(spec));
        const Detected gpu = detect(*f.gpu, f.camera, size);
        const CpuPixels cpu = raycastLargestLayers(*f.gpu, f.camera, size);
        REQUIRE(gpu.pixels.largestLayer.size() == std::size_t(pixels));
        int coverage = 0, differ = 0, tied = 0, nearCut = 0;
        CoplanarityStats fromPixels;
        for (int i = 0; i < pixels; ++i) {
            fromPixels.add(int(gpu.pixels.largestLayer[std::size_t(i)]), 0, int(gpu.pixels.fragments[std::size_t(i)]));
            // Where the rasterizer and the ray cast disagree on which surfaces cover the pixel
            // (a silhouette or shared edge on the pixel centre), the counts may differ.
            if (int(gpu.pixels.fragments[std::size_t(i)]) != cpu.fragments[std::size_t(i)]) {
                ++coverage;
                continue;
            }
            if (cpu.largestLayer[std::size_t(i)] >= 2) ++tied;
            if (int(gpu.pixels.largestLayer[std::size_t(i)]) == cpu.largestLayer[std::size_t(i)]) continue;
            if (cpu.nearTheCut[std::size_t(i)]) ++nearCut;
            else ++differ;
        }
        CHECK(differ == 0);
        // Disagreements where a gap is near the cut: intersection lines only, a few pixels.
        CHECK(nearCut <= pixels / 100);
        if (nearCut > 0) MESSAGE(spec << ": " << nearCut << " pixels near the cut disagree");
        if (differ > 0) {
            // How far apart the driver puts surfaces the ray cast finds coincident: the same
            // comparison at wider tie tolerances (a diagnostic for a GPU run; it prints only).
            for (double ulps : {256.0, 1024.0, 4096.0, 16384.0, 65536.0}) {
                Scene wider = makeBuiltinScene(spec);
                wider.depthTieUlps = ulps;
                test::Fixture g(std::move(wider));
                const Detected gw = detect(*g.gpu, g.camera, size);
                const CpuPixels cw = raycastLargestLayers(*g.gpu, g.camera, size);
                int differWide = 0;
                for (std::size_t i = 0; i < gw.pixels.largestLayer.size(); ++i)
                    if (int(gw.pixels.fragments[i]) == cw.fragments[i] && !cw.nearTheCut[i] &&
                        int(gw.pixels.largestLayer[i]) != cw.largestLayer[i])
                        ++differWide;
                MESSAGE(spec << ": at " << ulps << " ulps " << differWide << " pixels differ (" << differ << " at "
                             << f.gpu->scene().depthTieUlps << ")");
            }
        }
        // Coverage disagreements are edge pixels: a few percent of the image at most (48 of 1728
        // on cubes, whose face edges run through pixel centres, on llvmpipe).
        CHECK(coverage <= pixels / 25);
        // The totals the detector accumulated on the GPU are the per-pixel figures summed.
        const CoplanarityStats& s = *gpu.result.coplanarity;
        CHECK(s.pixelsByLargestLayer == fromPixels.pixelsByLargestLayer);
        CHECK(s.fragments == fromPixels.fragments);
        CHECK(s.fragments == *gpu.result.fragmentsTotal);
        CHECK(s.layers <= s.fragments);
        CHECK(s.pixels() == std::uint64_t(pixels));
        // The heatmap is Fig. 13's palette of the counts, to the 8-bit value a PNG stores.
        const Image expected = coplanarityHeatmap(gpu.pixels.largestLayer, size.x, size.y);
        int colourMismatch = 0;
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x)
                for (int c = 0; c < 3; ++c)
                    if (srgbByte(gpu.heatmap.at(x, y)[c]) != srgbByte(expected.at(x, y)[c])) ++colourMismatch;
        CHECK(colourMismatch == 0);
        if (spec.rfind("coplanar:", 0) == 0) {
            // K full-view coincident quads: every pixel one layer of exactly K, Fig. 13's colour for K.
            const int k = std::stoi(spec.substr(9));
            CHECK(coverage == 0);
            CHECK(tied == (k >= 2 ? pixels : 0));
            for (int i = 0; i < pixels; ++i) CHECK(gpu.pixels.largestLayer[std::size_t(i)] == std::uint32_t(k));
            const glm::vec3 colour = coplanarityColor(k);
            for (int c = 0; c < 3; ++c) CHECK(srgbByte(gpu.heatmap.at(size.x / 2, size.y / 2)[c]) == srgbByte(colour[c]));
            CHECK(s.coplanarityProbability() == (k >= 2 ? 1.0 : 0.0));
            CHECK(s.oneFragmentPerLayerRobustness() == doctest::Approx(1.0 / k));
        }
        if (spec.rfind("layers:", 0) == 0) {
            // Quads 0.25 apart: no rounding on any GPU brings them within the tie tolerance.
            CHECK(s.coplanarityProbability() == 0.0);
            CHECK(s.oneFragmentPerLayerRobustness() == 1.0);
        }
        if (spec == "cubes:separated") {
            // No face planes shared; only a pixel centre where two faces of one cube meet ties
            // (they are at one depth there), and which pixel centres land on such an edge depends
            // on the rasterizer's subpixel snapping: a few pixels at most, not none.
            CHECK(s.coplanarityProbability() <= 0.01);
            CHECK(s.oneFragmentPerLayerRobustness() >= 0.99);
        }
        if (spec == "cubes" || spec.rfind("shells:", 0) == 0) CHECK(s.coplanarityProbability() > 0.0);
    }
}

TEST_CASE("coplanarity detector: lists longer than the registers, tiles and submission order change nothing") {
    const glm::ivec2 size(24, 18);
    // 70 copies: past the resolve's 64 registers, so the selection walk counts the layer.
    {
        test::Fixture f(makeCoplanarScene(70));
        const Detected d = detect(*f.gpu, f.camera, size);
        for (auto v : d.pixels.largestLayer) CHECK(v == 70u);
        CHECK(d.result.coplanarity->pixelsByLargestLayer[kCoplanarityBins - 1] == std::uint64_t(size.x * size.y));
        CHECK(d.result.coplanarity->layers == std::uint64_t(size.x * size.y));
    }
    for (const std::string spec : {"cubes", "shells:3:roundoff", "default"}) {
        CAPTURE(spec);
        test::Fixture f(makeBuiltinScene(spec));
        const Detected whole = detect(*f.gpu, f.camera, size);
        FrameOptions tiled;
        tiled.coplanarityMaxBlockMiB = 0.01;  // 436 nodes: far fewer than the frame's fragments
        const Detected tiles = detect(*f.gpu, f.camera, size, tiled);
        FrameOptions reversed;
        reversed.reverseSubmission = true;
        const Detected flipped = detect(*f.gpu, f.camera, size, reversed);
        // Integer counts, not depths: coverage does not depend on the scissor or the draw order,
        // and the depths of one surface differ by a few ulps at most between the runs, far inside
        // the 64-ulp tie tolerance, so the layers are the same on any GPU.
        CHECK(tiles.pixels.largestLayer == whole.pixels.largestLayer);
        CHECK(tiles.pixels.fragments == whole.pixels.fragments);
        CHECK(tiles.result.coplanarity->pixelsByLargestLayer == whole.result.coplanarity->pixelsByLargestLayer);
        CHECK(tiles.result.coplanarity->layers == whole.result.coplanarity->layers);
        CHECK(flipped.pixels.largestLayer == whole.pixels.largestLayer);
        CHECK(flipped.result.coplanarity->layers == whole.result.coplanarity->layers);
    }
}

TEST_CASE("coplanarity detector: the tiles it needs, and a scene with nothing transparent is all grey") {
    const glm::ivec2 size(24, 18);
    {
        test::Fixture f(makeCoplanarScene(4));
        test::glContext();
        FrameRenderer renderer;
        FrameOptions options;
        options.detectCoplanarity = true;
        options.coplanarityMaxBlockMiB = 0.01;
        renderer.render(*f.gpu, f.camera, size, nullptr, options);
        gl::checkGl("tiled detect");
        // 4 * 432 fragments in pools of 436 nodes: at least four tiles.
        CHECK(renderer.coplanarity()->tiles() >= 4);
        CHECK(renderer.coplanarity()->passes() >= 2 * renderer.coplanarity()->tiles());
    }
    Scene opaqueOnly = makeLayersScene(2);
    for (auto& m : opaqueOnly.materials) m.alphaMode = AlphaMode::Opaque;
    test::Fixture f(std::move(opaqueOnly));
    REQUIRE_FALSE(f.gpu->hasTransparency());
    const Detected d = detect(*f.gpu, f.camera, size);
    CHECK(d.result.coplanarity->pixelsByLargestLayer[0] == std::uint64_t(size.x * size.y));
    CHECK(d.result.coplanarity->coplanarityProbability() == 0.0);
    for (int c = 0; c < 3; ++c) CHECK(srgbByte(d.heatmap.at(3, 3)[c]) == 0x80);
}
