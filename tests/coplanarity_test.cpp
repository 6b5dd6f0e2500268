// The CPU side of the coplanarity heatmap (render/coplanarity.hpp): Fig. 13's palette, the
// largest-layer rule on eye depths, and the C_p / R_h figures.
#include "image/image.hpp"
#include "render/coplanarity.hpp"
#include "render/depth_order.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace strata;

namespace {

int srgbByte(float linear) { return int(std::lround(linearToSrgb(linear) * 255.0f)); }

}  // namespace

TEST_CASE("coplanarity palette: Fig. 13's colours as 8-bit sRGB, grey for 0 and 1, brown from 9") {
    struct Entry { int layer; int r, g, b; const char* name; };
    const Entry entries[] = {
        {0, 0x80, 0x80, 0x80, "grey"},  {1, 0x80, 0x80, 0x80, "grey"},    {2, 0xFF, 0x00, 0x00, "red"},
        {3, 0x00, 0x00, 0xFF, "blue"},  {4, 0x00, 0x80, 0x00, "green"},   {5, 0x00, 0xFF, 0xFF, "cyan"},
        {6, 0x7F, 0xFF, 0xD4, "aquamarine"}, {7, 0xFF, 0x00, 0xFF, "fuchsia"}, {8, 0xFF, 0xFF, 0x00, "yellow"},
        {9, 0xA5, 0x2A, 0x2A, "brown"}, {16, 0xA5, 0x2A, 0x2A, "brown"},  {1000, 0xA5, 0x2A, 0x2A, "brown"},
    };
    for (const auto& e : entries) {
        CAPTURE(e.layer);
        const glm::vec3 c = coplanarityColor(e.layer);
        CHECK(srgbByte(c.r) == e.r);
        CHECK(srgbByte(c.g) == e.g);
        CHECK(srgbByte(c.b) == e.b);
        CHECK(std::string(coplanarityColorName(e.layer)) == e.name);
    }
}

TEST_CASE("largest depth layer: ties within the relative tolerance, in any order, chains included") {
    const double tol = tieToleranceFromUlps(64.0);
    int layers = -1;
    CHECK(largestDepthLayer({}, tol, &layers) == 0);
    CHECK(layers == 0);
    CHECK(largestDepthLayer({2.0f}, tol, &layers) == 1);
    CHECK(layers == 1);
    // Three coincident at 2, two at 5, one at 3, given out of order.
    CHECK(largestDepthLayer({5.0f, 2.0f, 3.0f, 2.0f, 5.0f, 2.0f}, tol, &layers) == 3);
    CHECK(layers == 3);
    // Round-off apart (a few ulps) is one layer; farther than the tolerance is not.
    const float a = 10.0f, b = std::nextafter(std::nextafter(a, 11.0f), 11.0f);
    CHECK(largestDepthLayer({a, b}, tol) == 2);
    CHECK(largestDepthLayer({a, a * float(1.0 + 4.0 * tol)}, tol) == 1);
    // A chain of steps each within the tolerance is one layer, as orderFragments cuts it.
    const float step = float(0.9 * tol);
    CHECK(largestDepthLayer({1.0f, 1.0f + step, 1.0f + 2.0f * step, 1.0f + 3.0f * step}, tol, &layers) == 4);
    CHECK(layers == 1);
}

TEST_CASE("coplanarity stats: C_p over pixels with fragments, one-per-layer R_h") {
    CoplanarityStats s;
    CHECK(s.coplanarityProbability() == 0.0);
    CHECK(s.oneFragmentPerLayerRobustness() == 1.0);
    s.add(0, 0, 0);  // background
    s.add(1, 2, 2);  // two separate layers
    s.add(3, 1, 3);  // three coincident
    s.add(12, 2, 13);
    CHECK(s.pixels() == 4);
    CHECK(s.pixelsWithFragments() == 3);
    CHECK(s.pixelsWithTies() == 2);
    CHECK(s.pixelsByLargestLayer[kCoplanarityBins - 1] == 1);
    CHECK(s.coplanarityProbability() == doctest::Approx(2.0 / 3.0));
    CHECK(s.oneFragmentPerLayerRobustness() == doctest::Approx(5.0 / 18.0));
    const Image heat = coplanarityHeatmap({0, 2, 3, 12}, 2, 2);
    CHECK(srgbByte(heat.at(1, 0).r) == 0xFF);   // red
    CHECK(srgbByte(heat.at(0, 1).b) == 0xFF);   // blue
    CHECK(srgbByte(heat.at(1, 1).r) == 0xA5);   // brown
    CHECK_THROWS_AS(coplanarityHeatmap({1, 2, 3}, 2, 2), std::invalid_argument);
}

TEST_CASE("coplanarity highlight: only pixels with a shared layer take their colour") {
    Image shaded(3, 1);
    for (int x = 0; x < 3; ++x) shaded.set(x, 0, glm::vec4(0.2f, 0.4f, 0.6f, 1.0f));
    const Image out = coplanarityHighlight(shaded, {0, 1, 3}, 0.5f);
    CHECK(out.at(0, 0) == shaded.at(0, 0));  // nothing there
    CHECK(out.at(1, 0) == shaded.at(1, 0));  // one fragment per layer
    const glm::vec3 blue = coplanarityColor(3);
    const glm::vec4 mixed = out.at(2, 0);
    CHECK(mixed.r == doctest::Approx(0.5f * 0.2f + 0.5f * blue.r));
    CHECK(mixed.g == doctest::Approx(0.5f * 0.4f + 0.5f * blue.g));
    CHECK(mixed.b == doctest::Approx(0.5f * 0.6f + 0.5f * blue.b));
    CHECK(mixed.a == 1.0f);
    CHECK_THROWS_AS(coplanarityHighlight(shaded, {0, 1}), std::invalid_argument);
    CHECK_THROWS_AS(coplanarityHighlight(shaded, {0, 1, 2}, 1.5f), std::invalid_argument);
}
