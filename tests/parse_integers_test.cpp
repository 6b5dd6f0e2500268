// Integer pairs from command-line text (io/parse_integers.hpp): whole values in int's range or
// nothing, where sscanf("%d") was undefined past the range and accepted leading spaces.
#include "io/parse_integers.hpp"

#include <doctest/doctest.h>

using namespace strata;

TEST_CASE("parseIntPair: a size and a pixel, whole or not at all") {
    CHECK(parseIntPair("640x480", "xX") == std::pair<int, int>{640, 480});
    CHECK(parseIntPair("640X480", "xX") == std::pair<int, int>{640, 480});
    CHECK(parseIntPair("12,-3", ",") == std::pair<int, int>{12, -3});
    CHECK(parseIntPair("2147483647x1", "xX") == std::pair<int, int>{2147483647, 1});
    for (const char* bad : {"2147483648x1", "99999999999999999999x1", "640x", "x480", "640x480x", "640 x480",
                            " 640x480", "640x480 ", "+640x480", "640*480", "", "x", "6.5x4", "0x10x"}) {
        CAPTURE(bad);
        CHECK_FALSE(parseIntPair(bad, "xX").has_value());
    }
    CHECK_FALSE(parseIntPair("1,2,3", ",").has_value());
}
