// The per-object LOD decision (lod/lod_select.hpp): every branch, with a synthetic cost model
// and a 90-degree, 100 x 100 view (50 px per unit of tangent) so sizes and errors are exact.
#include "lod/lod_select.hpp"

#include "camera/camera.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <initializer_list>
#include <numbers>
#include <stdexcept>
#include <string>

using namespace strata;
using namespace strata::lod;

namespace {

constexpr double kPi = std::numbers::pi;

// Geometry 0.05 ms + 10 ms per million triangles + 0.5 ms per million pixels; impostor 0.1 ms
// + 2 ms per million layer pixels.
LodCostModel synthetic() {
    LodCostModel m;
    m.geometryFixedMs = 0.05;
    m.geometryMsPerMegatriangle = 10.0;
    m.geometryMsPerMegapixel = 0.5;
    m.impostorFixedMs = 0.1;
    m.impostorMsPerMegapixel = 2.0;
    return m;
}

LodView view() {
    LodView v;
    v.eye = {0.0f, 0.0f, 0.0f};
    v.fovYRadians = kPi / 2;
    v.imageSize = {100, 100};
    return v;
}

// A unit sphere `distance` down -Z with 100 000 triangles and a 16-slice, 64-texel impostor
// seen 0.2 rad from its nearest view. Its slices have no overlap and its rays are parallel, so
// its parallax is the half-slice bound d sin a / 2L (lod_error.hpp; the bake's own terms are
// checked once below).
LodObjectInput object(float distance, std::uint64_t triangles = 100000) {
    LodObjectInput o;
    o.center = {0.0f, 0.0f, -distance};
    o.radius = 1.0f;
    o.triangles = triangles;
    o.hasImpostor = true;
    o.impostor.id = 0;
    o.impostor.slices = 16;
    o.impostor.resolution = 64;
    o.impostor.viewAngleRadians = 0.2;
    o.impostor.overlap = 0.0;
    o.impostor.apexHalfAngleRadians = 0.0;
    o.impostor.bytes = 1000;
    return o;
}

LodSelectOptions mode(LodMode m) {
    LodSelectOptions o;
    o.mode = m;
    return o;
}

// object(10) (10.0504 px, 16 slices) with coarser levels of 8 and 4 slices, drawn fraction 1 and
// one quad a slice each; and its error at L slices, px sin 0.2 / (2L) + px / 64.
LodObjectInput withLevels() {
    LodObjectInput o = object(10.0f);
    o.impostor.coarserLevels = 2;
    o.impostor.coarser[0] = {8, 1.0, 8.0};
    o.impostor.coarser[1] = {4, 1.0, 4.0};
    return o;
}
double errorAtSlices(int slices) {
    const double px = 100.0 / std::sqrt(99.0);
    return px * std::sin(0.2) / (2.0 * slices) + px / 64.0;
}

}  // namespace

TEST_CASE("lod select: mode names parse and print; anything else is a clear error") {
    for (LodMode m : {LodMode::Geometry, LodMode::Impostors, LodMode::Auto}) CHECK(parseLodMode(to_string(m)) == m);
    CHECK(std::string(to_string(LodMode::Impostors)) == "impostors");
    for (const char* bad : {"", "Auto", "impostor", "geometry ", "all"}) {
        CAPTURE(bad);
        CHECK_THROWS_WITH_AS(parseLodMode(bad),
                             ("lod mode '" + std::string(bad) + "' is not one of geometry|impostors|auto").c_str(),
                             std::invalid_argument);
    }
}

TEST_CASE("lod select: a far dense object becomes an impostor with its predictions and error") {
    // d = 10: projected 2 x 50 / sqrt(99) = 10.0504 px; geometry 0.05 + 1.0 + 0.5 x pi/4 x 101.01e-6;
    // impostor 0.1 + 2 x 16 x 101.01e-6 = 0.103232 ms; error 10.0504 (sin 0.2 / 32 + 1 / 64).
    const LodDecision d = selectLodFor(object(10.0f), view(), synthetic());
    const double px = 100.0 / std::sqrt(99.0);
    CHECK(d.impostor);
    CHECK(d.reason == LodReason::ImpostorCheaper);
    CHECK(d.distance == doctest::Approx(10.0));
    CHECK(d.projectedPx == doctest::Approx(px));
    CHECK(d.geometryMs == doctest::Approx(1.05 + 0.5 * kPi / 4 * px * px * 1e-6));
    CHECK(d.impostorMs == doctest::Approx(0.1 + 2.0 * 16 * px * px * 1e-6));
    CHECK(d.parallaxPx == doctest::Approx(px * std::sin(0.2) / 32.0));
    CHECK(d.samplingPx == doctest::Approx(px / 64.0));
    CHECK(d.errorPx == doctest::Approx(d.parallaxPx + d.samplingPx));
    // The default bake's overlap (0.5) and apex (3r, h = asin 1/3) enter the bound:
    // px x 1 x sin(0.2 + h) / (16 cos h).
    LodObjectInput baked = object(10.0f);
    baked.impostor.overlap = 0.5;
    baked.impostor.apexHalfAngleRadians = std::asin(1.0 / 3.0);
    const double h = std::asin(1.0 / 3.0);
    CHECK(selectLodFor(baked, view(), synthetic()).parallaxPx == doctest::Approx(px * std::sin(0.2 + h) / (16.0 * std::cos(h))));
}

TEST_CASE("lod select: a light object stays geometry (geometry cheaper)") {
    // 1000 triangles: 0.05 + 0.01 + ~0 = 0.06004 ms < the impostor's 0.1032 ms.
    const LodDecision d = selectLodFor(object(10.0f, 1000), view(), synthetic());
    CHECK_FALSE(d.impostor);
    CHECK(d.reason == LodReason::GeometryCheaper);
    CHECK(d.geometryMs == doctest::Approx(0.06004).epsilon(1e-4));
    // Forced, it is an impostor all the same.
    const LodDecision forced = selectLodFor(object(10.0f, 1000), view(), synthetic(), mode(LodMode::Impostors));
    CHECK(forced.impostor);
    CHECK(forced.reason == LodReason::ImpostorsForced);
}

TEST_CASE("lod select: error above the bound keeps geometry in auto, not when forced") {
    // d = sqrt(7.25): projected 100 / 2.5 = 40 px. At 30 degrees with 2 slices: parallax
    // 40 x 0.5 / 4 = 5 px, sampling 40 / 64 = 0.625 px: 5.625 px > 4.
    LodObjectInput o = object(std::sqrt(7.25f));
    o.impostor.slices = 2;
    o.impostor.viewAngleRadians = kPi / 6;
    const LodDecision d = selectLodFor(o, view(), synthetic());
    CHECK(d.projectedPx == doctest::Approx(40.0).epsilon(1e-5));
    CHECK(d.errorPx == doctest::Approx(5.625).epsilon(1e-5));
    CHECK_FALSE(d.impostor);
    CHECK(d.reason == LodReason::ErrorAboveBound);
    // A looser bound lets the cost decide: impostor 0.1 + 2 x 2 x 1600e-6 = 0.1064 < geometry 1.05.
    LodSelectOptions loose;
    loose.maxErrorPx = 6.0;
    CHECK(selectLodFor(o, view(), synthetic(), loose).reason == LodReason::ImpostorCheaper);
    // 4 slices: parallax 2.5 + 0.625 = 3.125 px <= 4: accepted at the default bound.
    o.impostor.slices = 4;
    CHECK(selectLodFor(o, view(), synthetic()).reason == LodReason::ImpostorCheaper);
    o.impostor.slices = 2;
    CHECK(selectLodFor(o, view(), synthetic(), mode(LodMode::Impostors)).impostor);
}

TEST_CASE("lod select: eye inside or too close is geometry in every mode, even impostors") {
    for (LodMode m : {LodMode::Auto, LodMode::Impostors, LodMode::Geometry}) {
        CAPTURE(to_string(m));
        const LodDecision inside = selectLodFor(object(0.5f), view(), synthetic(), mode(m));
        CHECK_FALSE(inside.impostor);
        CHECK(inside.reason == LodReason::EyeInside);
        const LodDecision close = selectLodFor(object(1.5f), view(), synthetic(), mode(m));
        CHECK_FALSE(close.impostor);
        CHECK(close.reason == LodReason::TooClose);
        CHECK(explain(close, object(1.5f), mode(m)) == "geometry: too close (distance 1.5 < 2 x radius 1)");
    }
    // Exactly 2 radii is no longer too close.
    CHECK(selectLodFor(object(2.0f), view(), synthetic(), mode(LodMode::Impostors)).reason == LodReason::ImpostorsForced);
    // A huge object (radius 1000, centre 50 away): the eye is inside its bounds.
    LodObjectInput huge = object(50.0f);
    huge.radius = 1000.0f;
    const LodDecision h = selectLodFor(huge, view(), synthetic(), mode(LodMode::Impostors));
    CHECK(h.reason == LodReason::EyeInside);
    CHECK(std::isinf(h.projectedPx));
    // Its geometry prediction still stands, with covered pixels clipped to the image: 0.05 + 1.0
    // + 0.5 x 1e4 x 1e-6.
    CHECK(h.geometryMs == doctest::Approx(1.055));  // covers the whole image
}

TEST_CASE("lod select: forced geometry, no impostor, no triangles, a flat object") {
    const LodDecision g = selectLodFor(object(10.0f), view(), synthetic(), mode(LodMode::Geometry));
    CHECK_FALSE(g.impostor);
    CHECK(g.reason == LodReason::GeometryForced);
    CHECK(g.impostorMs > 0.0);  // still predicted, for the panel
    LodObjectInput none = object(10.0f);
    none.hasImpostor = false;
    for (LodMode m : {LodMode::Auto, LodMode::Impostors}) {
        const LodDecision d = selectLodFor(none, view(), synthetic(), mode(m));
        CHECK(d.reason == LodReason::NoImpostor);
        CHECK(d.impostorMs == 0.0);
    }
    const LodDecision empty = selectLodFor(object(10.0f, 0), view(), synthetic(), mode(LodMode::Impostors));
    CHECK_FALSE(empty.impostor);
    CHECK(empty.reason == LodReason::NoTriangles);
    // A flat object (a quad: its bounding sphere's radius is half its diagonal) is decided like
    // any other; a degenerate one with radius 0 costs nothing per pixel and has no error.
    LodObjectInput flat = object(10.0f);
    flat.radius = 0.0f;
    const LodDecision f = selectLodFor(flat, view(), synthetic());
    CHECK(f.projectedPx == 0.0);
    CHECK(f.errorPx == 0.0);
    CHECK(f.impostorMs == doctest::Approx(0.1));
    CHECK(f.reason == LodReason::ImpostorCheaper);
}

TEST_CASE("lod select: totals count a shared impostor's memory once") {
    std::vector<LodObjectInput> objects;
    for (int i = 0; i < 3; ++i) objects.push_back(object(10.0f + float(i)));  // id 0, 1000 bytes each
    LodObjectInput own = object(20.0f);
    own.impostor.id = -1;
    own.impostor.bytes = 500;
    objects.push_back(own);
    LodObjectInput near = object(1.5f);  // too close: geometry, its impostor not counted
    near.impostor.id = 8;
    near.impostor.bytes = 300;
    objects.push_back(near);
    const LodSelection s = selectLod(objects, view(), synthetic());
    REQUIRE(s.objects.size() == 5);
    CHECK(s.impostorObjects == 4);
    CHECK(s.impostorsUsed == 2);
    CHECK(s.impostorBytes == 1500);
    double chosen = 0.0, geometry = 0.0;
    for (const auto& d : s.objects) {
        chosen += d.impostor ? d.impostorMs : d.geometryMs;
        geometry += d.geometryMs;
    }
    CHECK(s.predictedMs == doctest::Approx(chosen));
    CHECK(s.geometryOnlyMs == doctest::Approx(geometry));
    CHECK(s.predictedMs < s.geometryOnlyMs);
    // Forced geometry: nothing is an impostor, nothing is counted.
    const LodSelection g = selectLod(objects, view(), synthetic(), mode(LodMode::Geometry));
    CHECK(g.impostorObjects == 0);
    CHECK(g.impostorBytes == 0);
    CHECK(g.predictedMs == doctest::Approx(g.geometryOnlyMs));
}

TEST_CASE("lod select: the view from a camera") {
    Camera camera;
    camera.position = {1.0f, 2.0f, 3.0f};
    camera.fovYDegrees = 60.0f;
    const LodView v = lodView(camera, {640, 480});
    CHECK(v.eye == glm::vec3(1.0f, 2.0f, 3.0f));
    CHECK(v.fovYRadians == doctest::Approx(kPi / 3));
    CHECK(v.imageSize == glm::ivec2(640, 480));
}

TEST_CASE("lod select: a transparent object stays geometry in auto, becomes an impostor only when forced") {
    LodObjectInput o = object(10.0f);
    o.transparent = true;
    const LodDecision a = selectLodFor(o, view(), synthetic());
    CHECK(!a.impostor);
    CHECK(a.reason == LodReason::TransparentAuto);
    CHECK(a.impostorMs > 0.0);  // still predicted, for the panel
    CHECK(selectLodFor(o, view(), synthetic(), {LodMode::Impostors, kDefaultMaxErrorPx}).impostor);
}

TEST_CASE("lod select: a two-peel impostor's fill counts both peels' rectangles") {
    // drawnFraction 1.5 of the slice squares over 2 peels: 1.5 x the one-peel fill, not clamped to 1.
    LodObjectInput o = object(10.0f);
    o.impostor.peels = 2;
    o.impostor.drawnFraction = 1.5;
    const double px = 100.0 / std::sqrt(99.0);
    CHECK(selectLodFor(o, view(), synthetic()).impostorMs == doctest::Approx(0.1 + 2.0 * 16 * px * px * 1.5e-6));
    o.impostor.drawnFraction = 3.0;  // more than the peels can cover: clamped to 2
    CHECK(selectLodFor(o, view(), synthetic()).impostorMs == doctest::Approx(0.1 + 2.0 * 16 * px * px * 2e-6));
}

TEST_CASE("lod select: a stand-in pays its share of a draw, its quads and their sides") {
    // 0.1 ms a draw shared by 10 stand-ins, 0.001 ms a stand-in, 0.2 ms per 1000 quads, 0.1 ms
    // per 1000 pixels of quad side: 12 quads over 16 x s^2 layer pixels (s = 10.0504) have
    // sqrt(12 x 16 s^2) pixels of side.
    LodCostModel m = synthetic();
    m.impostorInstanceMs = 0.001;
    m.impostorMsPerKiloquad = 0.2;
    m.impostorMsPerKilosidePx = 0.1;
    LodObjectInput o = object(10.0f);
    o.impostor.quads = 12.0;
    o.standInDraws = 0.1;
    const double px = 100.0 / std::sqrt(99.0), layer = 16.0 * px * px;
    const double expected = 0.01 + 0.001 + 0.2 * 12e-3 + 0.1 * std::sqrt(12.0 * layer) * 1e-3 + 2.0 * layer * 1e-6;
    CHECK(selectLodFor(o, view(), m).impostorMs == doctest::Approx(expected));
    // No quad count: one quad a slice.
    o.impostor.quads = 0.0;
    CHECK(selectLodFor(o, view(), m).impostorMs ==
          doctest::Approx(0.01 + 0.001 + 0.2 * 16e-3 + 0.1 * 16.0 * px * 1e-3 + 2.0 * layer * 1e-6));
}

TEST_CASE("lod select: auto draws the cheapest level of merged slices within the bound; forced draws the baked one") {
    // The 16-slice impostor at d = 10 (10.0504 px) with coarser levels of 8 and 4 slices, drawn
    // fraction 1 and one quad a slice each. Errors at 0.2 rad: parallax 10.0504 sin 0.2 / (2L) =
    // 0.0624 (16), 0.1248 (8), 0.2497 (4) px, sampling 0.157 px; layer pixels L x 101.01: each
    // level halves the impostor's pixel part.
    LodObjectInput o = withLevels();
    const double px = 100.0 / std::sqrt(99.0);
    const auto errorAt = errorAtSlices;

    const LodDecision coarsest = selectLodFor(o, view(), synthetic());
    CHECK(coarsest.impostor);
    CHECK(coarsest.level == 2);
    CHECK(coarsest.errorPx == doctest::Approx(errorAt(4)));
    CHECK(coarsest.layerPixels == doctest::Approx(4.0 * px * px));
    CHECK(coarsest.impostorMs == doctest::Approx(0.1 + 2.0 * 4 * px * px * 1e-6));

    // A bound between the 8- and 4-slice errors: the 8-slice level.
    LodSelectOptions tight = mode(LodMode::Auto);
    tight.maxErrorPx = 0.5 * (errorAt(8) + errorAt(4));
    const LodDecision middle = selectLodFor(o, view(), synthetic(), tight);
    CHECK(middle.impostor);
    CHECK(middle.level == 1);
    CHECK(middle.errorPx == doctest::Approx(errorAt(8)));

    // A bound only the baked slices meet: level 0, as without levels.
    tight.maxErrorPx = 0.5 * (errorAt(16) + errorAt(8));
    const LodDecision baked = selectLodFor(o, view(), synthetic(), tight);
    CHECK(baked.impostor);
    CHECK(baked.level == 0);
    CHECK(baked.impostorMs == doctest::Approx(0.1 + 2.0 * 16 * px * px * 1e-6));

    // Forced impostors draw the baked slices whatever the bound.
    const LodDecision forced = selectLodFor(o, view(), synthetic(), mode(LodMode::Impostors));
    CHECK(forced.level == 0);

    // A coarser level that draws more (its merged rectangles larger than the slices they merge:
    // 8 x 0.5 and 4 x 0.9 of the square against 16 x 0.2) is not taken: the level must be
    // cheaper, not only within the bound.
    o.impostor.drawnFraction = 0.2;
    o.impostor.coarser[0] = {8, 0.5, 8.0};
    o.impostor.coarser[1] = {4, 0.9, 4.0};
    CHECK(selectLodFor(o, view(), synthetic()).level == 0);
}

TEST_CASE("lod select: with a level base, a coarser level may add only the bound's raise over it") {
    // The impostor above (16 slices, levels of 8 and 4; 10.0504 px at 0.2 rad). Errors:
    // e(L) = px sin 0.2 / (2L) + px / 64; a coarser level adds e(8) - e(16) = 0.0624 px and
    // e(4) - e(16) = 0.1872 px.
    LodObjectInput o = withLevels();
    const double px = 100.0 / std::sqrt(99.0);
    const auto errorAt = errorAtSlices;
    LodSelectOptions budget = mode(LodMode::Auto);
    budget.levelBasePx = 0.5;
    // At the base itself (no raise): the baked slices, although every level is within 0.5 px.
    budget.maxErrorPx = 0.5;
    CHECK(errorAt(4) < 0.5);
    CHECK(selectLodFor(o, view(), synthetic(), budget).level == 0);
    // Raised by 0.1 px: the 8-slice level adds 0.0624 (taken), the 4-slice 0.1872 (not).
    budget.maxErrorPx = 0.6;
    const LodDecision raised = selectLodFor(o, view(), synthetic(), budget);
    CHECK(raised.level == 1);
    CHECK(raised.errorPx - errorAt(16) == doctest::Approx(px * std::sin(0.2) / 32.0));
    // Raised by 0.2 px: the 4-slice level too.
    budget.maxErrorPx = 0.7;
    CHECK(selectLodFor(o, view(), synthetic(), budget).level == 2);
    // Without a base (0) any level within the bound, as before: the 4-slice one at 0.5.
    budget.levelBasePx = 0.0;
    budget.maxErrorPx = 0.5;
    CHECK(selectLodFor(o, view(), synthetic(), budget).level == 2);
}
