// Image::averageDown: the antialiased version of a supersampled frame (bench's
// --reference-supersample), a block's mean per pixel.
#include "image/image.hpp"

#include <doctest/doctest.h>

#include <stdexcept>

using namespace strata;

TEST_CASE("averageDown takes each block's mean and refuses a size the factor does not divide") {
    Image big(4, 2);
    // Left block: 0, 1, 2, 3 in red; right block all 0.5; alpha 1 throughout.
    big.set(0, 0, {0.0f, 0.0f, 0.0f, 1.0f});
    big.set(1, 0, {1.0f, 0.0f, 0.0f, 1.0f});
    big.set(0, 1, {2.0f, 0.0f, 0.0f, 1.0f});
    big.set(1, 1, {3.0f, 0.0f, 0.0f, 1.0f});
    for (int y = 0; y < 2; ++y)
        for (int x = 2; x < 4; ++x) big.set(x, y, {0.5f, 0.25f, 0.125f, 1.0f});
    const Image small = averageDown(big, 2);
    REQUIRE(small.width == 2);
    REQUIRE(small.height == 1);
    CHECK(small.at(0, 0).r == doctest::Approx(1.5));
    CHECK(small.at(0, 0).a == doctest::Approx(1.0));
    CHECK(small.at(1, 0).g == doctest::Approx(0.25));
    CHECK(small.at(1, 0).b == doctest::Approx(0.125));
    // Factor 1 is the image itself.
    CHECK(averageDown(big, 1).rgba == big.rgba);
    CHECK_THROWS_AS(averageDown(big, 3), std::invalid_argument);
    CHECK_THROWS_AS(averageDown(big, 0), std::invalid_argument);
}
