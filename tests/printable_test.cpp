// printable / printableMessage: what a message may quote of a hostile input.
#include "io/printable.hpp"

#include <doctest/doctest.h>

#include <string>

using strata::printable;
using strata::printableMessage;

TEST_CASE("printable: control bytes, a backslash and non-UTF-8 bytes are escaped; UTF-8 is kept") {
    using namespace std::string_literals;
    CHECK(printable("plain 1.5e3") == "plain 1.5e3");
    CHECK(printable("a\nb\rc\td") == "a\\nb\\rc\\td");
    CHECK(printable("nul\0cut"s) == "nul\\0cut");          // a NUL no longer ends the message
    CHECK(printable("\x1b[2J") == "\\x1B[2J");               // a terminal escape sequence
    CHECK(printable("\x7f") == "\\x7F");
    CHECK(printable("back\\slash") == "back\\\\slash");
    CHECK(printable("caf\xc3\xa9 \xe2\x80\xa6") == "caf\xc3\xa9 \xe2\x80\xa6");  // café …
    CHECK(printable("\xff\xfe" "1\0"s) == "\\xFF\\xFE1\\0");  // a UTF-16 byte-order mark and a wide '1'
    CHECK(printable("\xc3") == "\\xC3");                       // a UTF-8 sequence cut short
    CHECK(printable("\xc0\xaf") == "\\xC0\\xAF");              // an overlong '/'
    CHECK(printable("\xed\xa0\x80") == "\\xED\\xA0\\x80");     // a UTF-16 surrogate
}

TEST_CASE("printable: a long token is cut with an ellipsis, at a character or escape boundary") {
    CHECK(printable(std::string(10, 'x'), 10) == std::string(10, 'x'));
    CHECK(printable(std::string(11, 'x'), 10) == std::string(10, 'x') + "...");
    // A 10 MB token costs a few bytes of message.
    std::string huge(10 << 20, '7');
    CHECK(printable(huge, 40) == std::string(40, '7') + "...");
    // An escape is never split: 9 plain characters and a 4-character escape do not fit in 10.
    CHECK(printable(std::string(9, 'a') + "\x01", 10) == std::string(9, 'a') + "...");
    // Nor is a UTF-8 character: each counts as one.
    CHECK(printable("\xc3\xa9\xc3\xa9\xc3\xa9", 2) == "\xc3\xa9\xc3\xa9...");
    CHECK(printable("", 5).empty());
}

TEST_CASE("printableMessage: short messages pass, long ones keep their head and tail") {
    CHECK(printableMessage("scene.glb: no such file") == "scene.glb: no such file");
    const std::string head = "/a/very/long/" + std::string(400, 'd') + "/model.glb";
    const std::string message = head + ": mesh 0 primitive 0: index 9 out of range (4 vertices)";
    const std::string out = printableMessage(message, 200);
    CHECK(out.size() == 200);
    CHECK(out.rfind("/a/very/long/ddd", 0) == 0);
    CHECK(out.find("...") != std::string::npos);
    CHECK(out.substr(out.size() - 18) == "range (4 vertices)");  // the cause survives
    // Far longer than any window: the same shape, bounded work.
    const std::string out2 = printableMessage(std::string(5 << 20, 'x') + " the cause", 100);
    CHECK(out2.size() == 100);
    CHECK(out2.substr(out2.size() - 9) == "the cause");
    CHECK(printableMessage("line\nbreak", 100) == "line\\nbreak");
}
