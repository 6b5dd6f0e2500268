// The LOD cost model's arithmetic (lod/lod_cost_model.hpp) with a synthetic device whose
// coefficients are round numbers, so every prediction and crossover is known exactly.
#include "lod/lod_cost_model.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>

using namespace strata::lod;

namespace {

// 10 ms per million triangles (100 M triangles/s), 0.5 ms per million covered pixels, 0.05 ms a
// draw; impostors 2 ms per million layer pixels (500 M/s), 0.02 ms a draw.
LodCostModel synthetic() {
    LodCostModel m;
    m.geometryFixedMs = 0.05;
    m.geometryMsPerMegatriangle = 10.0;
    m.geometryMsPerMegapixel = 0.5;
    m.impostorFixedMs = 0.02;
    m.impostorMsPerMegapixel = 2.0;
    return m;
}

}  // namespace

TEST_CASE("lod cost: predictions are fixed + slope x count") {
    const LodCostModel m = synthetic();
    CHECK(m.geometryMs(0.0, 0.0) == doctest::Approx(0.05));
    CHECK(m.geometryMs(100000.0, 0.0) == doctest::Approx(1.05));
    CHECK(m.geometryMs(100000.0, 1e6) == doctest::Approx(1.55));
    CHECK(m.impostorMs(0.0) == doctest::Approx(0.02));
    CHECK(m.impostorMs(160000.0) == doctest::Approx(0.34));
    // 16 slices each filling 100 x 100 pixels; a quarter of it left by the bounding rectangles.
    CHECK(impostorLayerPixels(100.0, 16) == doctest::Approx(160000.0));
    CHECK(impostorLayerPixels(100.0, 16, 0.25) == doctest::Approx(40000.0));
    CHECK(impostorLayerPixels(100.0, 256) == doctest::Approx(2560000.0));
    CHECK(impostorLayerPixels(100.0, 1) == doctest::Approx(10000.0));
}

TEST_CASE("lod cost: a bake is its mesh draws, each a geometry draw into half the image") {
    const LodCostModel m = synthetic();
    // 40 draws (20 views x 2 peels) + 30 hole-filling pairs of a 100 k-triangle mesh at 128^2:
    // each 0.05 + 1.0 + 0.5 x 8192 / 1e6 = 1.054096 ms.
    CHECK(predictedBakeMs(m, 100000.0, 70, 128) == doctest::Approx(70.0 * 1.054096));
    CHECK(predictedBakeMs(m, 100000.0, 0, 128) == 0.0);
    CHECK(predictedBakeMs(m, 200000.0, 70, 128) > predictedBakeMs(m, 100000.0, 70, 128));
}

TEST_CASE("lod cost: the crossover triangle count and size are each other's inverse (Fig. 8)") {
    const LodCostModel m = synthetic();
    // 100 px, 16 slices: impostor 0.02 + 2 x 0.16 = 0.34 ms; geometry without triangles
    // 0.05 + 0.5 x 0.01 = 0.055 ms; T = (0.34 - 0.055) / 10 ms per million = 28500.
    CHECK(crossoverTriangles(m, 100.0, 16) == doctest::Approx(28500.0));
    // And back: (2 x 16 - 0.5) s^2 1e-6 = 0.05 + 0.285 - 0.02 = 0.315  ->  s = 100.
    CHECK(crossoverSizePx(m, 28500.0, 16) == doctest::Approx(100.0));
    // More slices: the impostor costs more per pixel, so it needs a denser model at one size
    // and wins over a smaller area for one model.
    CHECK(crossoverTriangles(m, 100.0, 64) > crossoverTriangles(m, 100.0, 16));
    CHECK(crossoverSizePx(m, 28500.0, 64) < 100.0);
    // Larger on screen: a denser model is needed.
    CHECK(crossoverTriangles(m, 200.0, 16) > crossoverTriangles(m, 100.0, 16));
    // 256 slices at 10 px: 0.02 + 2 x 0.0256 = 0.0712 ms vs 0.05 + 0.5 x 1e-4 = 0.05005 ms.
    CHECK(crossoverTriangles(m, 10.0, 256) == doctest::Approx((0.0712 - 0.05005) / 10.0 * 1e6));
}

TEST_CASE("lod cost: crossover limits: always, never, free triangles") {
    LodCostModel m = synthetic();
    // An impostor below the geometry's fixed cost at that size is cheaper whatever the model.
    m.impostorFixedMs = 0.0;
    m.impostorMsPerMegapixel = 0.0;
    CHECK(crossoverTriangles(m, 100.0, 16) == 0.0);
    // Its cost does not grow with size: it wins at every size once it wins at all.
    CHECK(std::isinf(crossoverSizePx(m, 1000.0, 16)));
    // Triangles free: no triangle count makes a costlier impostor cheaper.
    m = synthetic();
    m.geometryMsPerMegatriangle = 0.0;
    CHECK(std::isinf(crossoverTriangles(m, 100.0, 16)));
    // A model with no triangles costs 0.05 ms; an impostor with a 0.1 ms fixed cost never wins.
    m = synthetic();
    m.impostorFixedMs = 0.1;
    CHECK(crossoverSizePx(m, 0.0, 16) == 0.0);
}

TEST_CASE("lod cost: a stand-in's share of a draw, its quads and their sides") {
    LodCostModel m = synthetic();
    m.impostorInstanceMs = 0.001;
    m.impostorMsPerKiloquad = 0.2;      // 0.2 us a quad
    m.impostorMsPerKilosidePx = 0.1;    // 0.1 us a pixel of a quad's side
    // 16 quads over 160000 layer pixels (100 x 100 each): 1600 pixels of side.
    // 0.02 x 0.25 + 0.001 + 0.0032 + 0.16 + 0.32.
    CHECK(m.impostorMs(160000.0, 16.0, 0.25) == doctest::Approx(0.4892));
    CHECK(m.impostorMs(0.0, 0.0, 0.0) == doctest::Approx(0.001));
    // The crossover size solves the quadratic the side term makes: at it both cost the same,
    // and the sides make it smaller than without them (100 px above).
    const double s = crossoverSizePx(m, 28500.0, 16);
    CHECK(m.impostorMs(impostorLayerPixels(s, 16), 16.0) == doctest::Approx(m.geometryMs(28500.0, s * s)));
    CHECK(s == doctest::Approx(77.13).epsilon(1e-3));
    CHECK(crossoverTriangles(m, s, 16) == doctest::Approx(28500.0));
    // Impostor pixels no dearer than geometry's, the sides alone grow it: a linear crossover.
    m.impostorMsPerMegapixel = 0.5 / 16.0;
    const double margin = m.geometryMs(28500.0, 0.0) - m.impostorMs(0.0, 16.0);
    CHECK(crossoverSizePx(m, 28500.0, 16) == doctest::Approx(margin / (0.1e-3 * 16.0)));
}
