// Where bounds land on screen (render/screen_rect.hpp): the pixel rectangles that scissor the
// full-screen passes to the transparent objects, stated for boxes whose projection is known.
// Eye at the origin looking down -z, 90 degrees, square 100 x 100 frame: a point (x, y, z) lands
// at NDC (x, y) / -z, pixel 50 + 50 * NDC.
#include "render/screen_rect.hpp"

#include <doctest/doctest.h>

#include <glm/gtc/matrix_transform.hpp>

using namespace strata;

namespace {

const glm::mat4 kViewProjection = glm::perspective(glm::radians(90.0f), 1.0f, 0.1f, 100.0f);
const glm::ivec2 kFrame(100, 100);

}  // namespace

TEST_CASE("a box's pixel rectangle: its corners' extent, one pixel more each side for round-off") {
    // Nearest face at z = -2: NDC +-0.5 (pixels 25 .. 75, a little more for the box's inflation).
    const Bounds box{{-1.0f, -1.0f, -3.0f}, {1.0f, 1.0f, -2.0f}};
    const ScreenProjection p = projectBox(kViewProjection, box);
    CHECK_FALSE(p.behindEye);
    CHECK(p.ndcMin.x == doctest::Approx(-0.5).epsilon(1e-3));
    CHECK(p.ndcMax.y == doctest::Approx(0.5).epsilon(1e-3));
    const PixelRect r = pixelRect(p, kFrame);
    CHECK(r.origin == glm::ivec2(23, 23));
    CHECK(r.size == glm::ivec2(54, 54));
}

TEST_CASE("a box's rectangle in cells of 8 pixels, as the object skipper's reduced bound reads it") {
    // Pixels 24.9 .. 75.1 (NDC +-0.5 and the inflation) lie in cells 3 .. 9 of 8 pixels; one more
    // each side: 2 .. 10, 9 cells.
    const Bounds box{{-1.0f, -1.0f, -3.0f}, {1.0f, 1.0f, -2.0f}};
    const ScreenProjection p = projectBox(kViewProjection, box);
    const PixelRect r = pixelRect(p, kFrame, 8);
    CHECK(r.origin == glm::ivec2(2, 2));
    CHECK(r.size == glm::ivec2(9, 9));
    // A frame of 100 pixels has 13 cells, the last one partial: the whole frame is all 13.
    const PixelRect all = pixelRect(ScreenProjection{}, kFrame, 8);
    CHECK(all.origin == glm::ivec2(0, 0));
    CHECK(all.size == glm::ivec2(13, 13));
}

TEST_CASE("the pixels an object reaches: the cube around its bounding sphere") {
    // A 2-unit cube centred 10 away: sphere radius sqrt(3), nearest face of the cube around it
    // at z = -10 + sqrt(3); half width sqrt(3) / (10 - sqrt(3)) = 0.2095 in NDC, 10.48 pixels.
    const Bounds box{{-1.0f, -1.0f, -11.0f}, {1.0f, 1.0f, -9.0f}};
    const PixelRect r = pixelsReached(kViewProjection, box, kFrame);
    CHECK(r.origin == glm::ivec2(38, 38));
    CHECK(r.size == glm::ivec2(24, 24));
}

TEST_CASE("a box reaching behind the eye covers the frame; one outside it or empty covers nothing") {
    const Bounds around{{-1.0f, -1.0f, -1.0f}, {1.0f, 1.0f, 1.0f}};
    CHECK(projectBox(kViewProjection, around).behindEye);
    const PixelRect all = pixelsReached(kViewProjection, around, kFrame);
    CHECK(all.origin == glm::ivec2(0, 0));
    CHECK(all.size == kFrame);
    // Right of the view: NDC x from 25 to 26.
    const Bounds right{{50.0f, -1.0f, -2.0f}, {52.0f, 1.0f, -2.0f}};
    CHECK(pixelsReached(kViewProjection, right, kFrame).empty());
    CHECK(pixelsReached(kViewProjection, Bounds{}, kFrame).empty());
}

TEST_CASE("united rectangles: the smallest holding both; an empty one adds nothing") {
    const PixelRect a{{10, 20}, {5, 5}}, b{{30, 5}, {10, 2}};
    const PixelRect u = a.unite(b);
    CHECK(u.origin == glm::ivec2(10, 5));
    CHECK(u.size == glm::ivec2(30, 20));
    CHECK(a.unite(PixelRect{}).origin == a.origin);
    CHECK(a.unite(PixelRect{}).size == a.size);
    CHECK(PixelRect{}.unite(b).size == b.size);
}
