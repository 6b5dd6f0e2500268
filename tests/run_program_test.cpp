// runProgram (io/run_program.hpp): input in, output and exit status out, without a shell, without
// a deadlock when both sides exceed a pipe's buffer, and a clear error for a missing program.
// boxDownscale (image/image.hpp), which the report's thumbnails use, is here too: a closed form.
#include "image/image.hpp"
#include "io/run_program.hpp"

#include <doctest/doctest.h>

#include <stdexcept>
#include <string>

using namespace strata;

TEST_CASE("runProgram: passes input, returns output and exit status, and names a missing program") {
    const ProgramResult cat = runProgram({"cat"}, "hello\n");
    CHECK(cat.exitCode == 0);
    CHECK(cat.output == "hello\n");
    // Arguments reach the program as given: no shell splits or expands them.
    const ProgramResult echo = runProgram({"printf", "%s|", "a b", "$HOME", "*"});
    CHECK(echo.output == "a b|$HOME|*|");
    CHECK(runProgram({"sh", "-c", "echo oops >&2; exit 3"}).exitCode == 3);
    CHECK(runProgram({"sh", "-c", "echo oops >&2; exit 3"}).output == "oops\n");
    // Four megabytes each way: more than a pipe holds, so both must flow at once.
    const std::string big(4u << 20, 'x');
    const ProgramResult through = runProgram({"cat"}, big);
    CHECK(through.exitCode == 0);
    CHECK(through.output.size() == big.size());
    // A program that reads nothing and exits: no SIGPIPE for us.
    CHECK(runProgram({"true"}, big).exitCode == 0);
    CHECK_THROWS_WITH_AS(runProgram({"strata-no-such-program"}), "strata-no-such-program: not found on PATH",
                         std::runtime_error);
    CHECK(programOnPath("sh"));
    CHECK_FALSE(programOnPath("strata-no-such-program"));
}

TEST_CASE("boxDownscale: each pixel is the mean of the block it covers, partial blocks included") {
    Image image(5, 3);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 5; ++x) image.set(x, y, glm::vec4(float(x), float(y), float(x * y), 1.0f));
    const Image half = boxDownscale(image, 2);
    REQUIRE(half.width == 3);
    REQUIRE(half.height == 2);
    CHECK(half.at(0, 0) == glm::vec4(0.5f, 0.5f, 0.25f, 1.0f));   // x 0..1, y 0..1
    CHECK(half.at(2, 0) == glm::vec4(4.0f, 0.5f, 2.0f, 1.0f));    // x 4 only, y 0..1
    CHECK(half.at(2, 1) == glm::vec4(4.0f, 2.0f, 8.0f, 1.0f));    // the corner pixel alone
    CHECK(boxDownscale(image, 1).rgba == image.rgba);
    CHECK_THROWS_AS(boxDownscale(image, 0), std::invalid_argument);
}
