// Trace files: animation-path round trip, the head-movement CSV layout, and malformed input
// failing with `file:line: what`.
#include "tracking/trace_io.hpp"

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

using namespace strata::tracking;

namespace {

std::string tempPath(const std::string& name) {
    return (std::filesystem::temp_directory_path() / ("strata_tracking_" + name)).string();
}

void writeText(const std::string& path, const std::string& text) {
    std::ofstream f(path);
    f << text;
}

// what() of the TraceError thrown while reading `text` stored as `name`.
std::string errorOf(const std::string& name, const std::string& text) {
    const std::string path = tempPath(name);
    writeText(path, text);
    try {
        (void)readTrace(path);
    } catch (const strata::TraceError& e) {
        std::filesystem::remove(path);
        return e.what();
    }
    std::filesystem::remove(path);
    return "no error";
}

}  // namespace

TEST_CASE("animation path: comments, blank lines, renormalisation and round trip") {
    std::istringstream in("# header\n\n0 1 2 3 0 0 0 1\n0.5 1 2 3.5 0 0.7071068 0 0.7071068  # trailing\n");
    const Trace t = parseAnimationPath(in, "mem");
    REQUIRE(t.size() == 2);
    CHECK(t[1].t == doctest::Approx(0.5));
    CHECK(t[1].p.z() == doctest::Approx(3.5));
    CHECK(t[1].q.norm() == doctest::Approx(1.0).epsilon(1e-15));

    const std::string text = formatAnimationPath(t, "two\nlines");
    CHECK(text.rfind("# strata animation path", 0) == 0);
    CHECK(text.find("\n# two\n# lines\n") != std::string::npos);
    std::istringstream written(text);
    const Trace back = parseAnimationPath(written, "written");
    REQUIRE(back.size() == t.size());
    for (std::size_t i = 0; i < t.size(); ++i) {
        CHECK(back[i].t == doctest::Approx(t[i].t).epsilon(1e-9));
        CHECK((back[i].p - t[i].p).norm() < 1e-6);
        CHECK(angleBetween(back[i].q, t[i].q) < 1e-8);
    }
}

TEST_CASE("animation path: malformed lines name file and line") {
    const std::string ok = "0 0 0 0 0 0 0 1\n";
    CHECK(errorOf("a.path", ok + "# c\n0.1 0 0 0 0 0 1\n") ==
          tempPath("a.path") + ":3: expected 8 fields `time px py pz qx qy qz qw`, found 7");
    CHECK(errorOf("b.path", ok + "0.1 0 zero 0 0 0 0 1\n").rfind(tempPath("b.path") + ":2: field 3 `zero`", 0) == 0);
    CHECK(errorOf("c.path", ok + "0.1 0 0 0 0 0 0 0\n") == tempPath("c.path") + ":2: quaternion is zero");
    CHECK(errorOf("d.path", ok + "0.1 0 0 0 0 0 0 2\n").rfind(tempPath("d.path") + ":2: quaternion is not unit", 0) == 0);
    CHECK(errorOf("e.path", "1 0 0 0 0 0 0 1\n0.5 0 0 0 0 0 0 1\n").rfind(tempPath("e.path") + ":2: time", 0) == 0);
    CHECK(errorOf("f.path", ok + "0.1 0 0 nan 0 0 0 1\n") == tempPath("f.path") + ":2: field 4 is not finite");
    // A position beyond float range turns every error figure into inf: refused, with its value.
    CHECK(errorOf("h.path", ok + "0.1 0 1e300 0 0 0 0 1\n") == tempPath("h.path") + ":2: position 1e+300 does not fit a float");
    // A 10 MB token is quoted cut; UTF-16 is named as such.
    CHECK(errorOf("i.path", ok + "0.1 " + std::string(10 << 20, 'z') + " 0 0 0 0 0 1\n") ==
          tempPath("i.path") + ":2: field 2 `" + std::string(40, 'z') + "...` is not a number");
    // A line of a million one-character fields is counted, not split into a million strings.
    std::string many;
    for (int i = 0; i < 1000000; ++i) many += "1 ";
    CHECK(errorOf("l.path", many + "\n") == tempPath("l.path") + ":1: expected 8 fields `time px py pz qx qy qz qw`, found 1000000");
    CHECK(errorOf("m.csv", std::string(2000, ',') + "\n") == tempPath("m.csv") + ":1: header has 2001 columns, more than 1024");
    CHECK(errorOf("j.path", std::string("\xff\xfe" "0\0 \0", 6)) == tempPath("j.path") + ":1: NUL byte: not a text file (UTF-16?)");
    CHECK(errorOf("k.csv", "Timestamp,UnitQuaternion.x,UnitQuaternion.y,UnitQuaternion.z,UnitQuaternion.w,HmdPosition.x,"
                           "HmdPosition.y,HmdPosition.z\n0,0,0,0,1,0,1e300,0\n") ==
          tempPath("k.csv") + ":2: position 1e+300 does not fit a float");
    // One line, no newline inside: the message is printable as is.
    CHECK(errorOf("g.path", "x\n").find('\n') == std::string::npos);
    try {
        (void)readTrace(tempPath("does-not-exist.path"));
        FAIL("no error");
    } catch (const strata::TraceError& e) {
        CHECK(std::string(e.what()) == tempPath("does-not-exist.path") + ": no such file");
    }
}

TEST_CASE("head-movement CSV: numeric and date-time timestamps, Unity frame converted") {
    const std::string header =
        "Timestamp,PlaybackTime,UnitQuaternion.x,UnitQuaternion.y,UnitQuaternion.z,UnitQuaternion.w,"
        "HmdPosition.x,HmdPosition.y,HmdPosition.z\n";
    {
        std::istringstream in(header + "10.0,0.0,0,0,0,1,0.1,0.2,0.3\n10.25,0.25,0.1,0.2,0.3,0.927362,0,0,1\n");
        const Trace t = parseHeadMovementCsv(in, "mem.csv");
        REQUIRE(t.size() == 2);
        CHECK(t[0].t == 0.0);
        CHECK(t[1].t == doctest::Approx(0.25));
        CHECK(t[0].p.z() == doctest::Approx(-0.3));  // mirrored Z
        CHECK(t[1].q.x() == doctest::Approx(-0.1).epsilon(1e-5));
        CHECK(t[1].q.z() == doctest::Approx(0.3).epsilon(1e-5));
    }
    {
        // Midnight crossing: date-time differences go through days, not time of day.
        std::istringstream in(header + "2016-12-31 23:59:59.900, 0, 0,0,0,1, 0,0,0\n"
                                       "2017-01-01 00:00:00.150, 0, 0,0,0,1, 0,0,0\n");
        const Trace t = parseHeadMovementCsv(in, "mem.csv");
        REQUIRE(t.size() == 2);
        CHECK(t[1].t == doctest::Approx(0.25).epsilon(1e-9));
    }
    double s = 0.0;
    CHECK(parseDateTimeSeconds("1970-01-02T00:00:01.5", s));
    CHECK(s == doctest::Approx(86401.5));
    CHECK_FALSE(parseDateTimeSeconds("yesterday", s));
    // Every field zero-padded digits: no sign, no space, no short field (sscanf took all three).
    CHECK_FALSE(parseDateTimeSeconds("1970-1-02T00:00:01", s));
    CHECK_FALSE(parseDateTimeSeconds("1970-01-02T+0:00:01", s));
    CHECK_FALSE(parseDateTimeSeconds(" 1970-01-02T00:00:01", s));
    CHECK_FALSE(parseDateTimeSeconds("1970-01-02X00:00:01", s));
    CHECK_FALSE(parseDateTimeSeconds("1970-01-02T00:00", s));
    CHECK(parseDateTimeSeconds("1970-01-01 00:01:02", s));
    CHECK(s == 62.0);
    CHECK(errorOf("h.csv", "Timestamp,Foo\n1,2\n") == tempPath("h.csv") + ":1: header lacks column `UnitQuaternion.x`");
    CHECK(errorOf("i.csv", header + "0,0,0,0,0,1,0,0,0\nnoon,0,0,0,0,1,0,0,0\n").rfind(tempPath("i.csv") + ":3: Timestamp", 0) == 0);
    CHECK(errorOf("j.csv", header + "0,0,0,0,0,1,0,0\n").rfind(tempPath("j.csv") + ":2: expected 9", 0) == 0);
}

TEST_CASE("head-movement CSV: a file laid out as the Wu et al. 2017 dataset ships it") {
    // Layout of the dataset's per-user, per-video files (Wu, Tan, Wang, Yang, "A Dataset for
    // Exploring User Behaviors in VR Spherical Video Streaming", MMSys 2017; files
    // Experiment_N/USER/video_K.csv), as its readme and the readers built on it use it:
    // the header `Timestamp,PlaybackTime,UnitQuaternion.x,UnitQuaternion.y,UnitQuaternion.z,
    // UnitQuaternion.w,HmdPosition.x,HmdPosition.y,HmdPosition.z`, Timestamp a wall-clock date-time
    // with sub-second digits, PlaybackTime the video's seconds, the HMD's Unity pose (left-handed,
    // +Z forward, metres). Written by a .NET logger: CRLF line ends and possibly a UTF-8 BOM;
    // .NET's default format gives seven fractional digits; a few samples repeat a time.
    // The rows below are in that layout (values made up): ~ 100 Hz, a 90-degree yaw in Unity.
    const std::string text =
        "\xEF\xBB\xBFTimestamp,PlaybackTime,UnitQuaternion.x,UnitQuaternion.y,UnitQuaternion.z,"
        "UnitQuaternion.w,HmdPosition.x,HmdPosition.y,HmdPosition.z\r\n"
        "2016-12-07 13:39:56.4180000,0.000,0,0,0,1,0.0012,-0.0031,0.0105\r\n"
        "2016-12-07 13:39:56.4280000,0.010,0,0.0174524,0,0.9998477,0.0012,-0.0031,0.0106\r\n"
        "2016-12-07 13:39:56.4280000,0.010,0,0.0174524,0,0.9998477,0.0012,-0.0031,0.0106\r\n"
        "2016-12-07 13:39:56.4390000,0.021,0,0.7071068,0,0.7071068,0.0013,-0.0030,0.0107\r\n";
    const std::string path = tempPath("wu2017.csv");
    writeText(path, text);
    const Trace t = readTrace(path);
    std::filesystem::remove(path);
    REQUIRE(t.size() == 4);
    CHECK(t[0].t == 0.0);
    // Within a microsecond: wall-clock seconds since 1970 carry ~2e-7 s of double round-off.
    CHECK(t[1].t == doctest::Approx(0.010).epsilon(1e-4));
    CHECK(t[2].t == t[1].t);  // a repeated time is kept; the predictors treat it as dt = 0
    CHECK(t[3].t == doctest::Approx(0.021).epsilon(1e-4));
    CHECK(t[0].p.z() == doctest::Approx(-0.0105));  // Unity's +Z forward is this project's -Z
    // Unity's +90 deg about +Y (left-handed: the view turns from +Z to +X, to the right) is, after
    // mirroring Z, a turn from -Z to +X: -90 deg about +Y in this right-handed frame.
    const Eigen::Vector3d forward = t[3].q * Eigen::Vector3d(0.0, 0.0, -1.0);
    CHECK((forward - Eigen::Vector3d(1.0, 0.0, 0.0)).norm() < 1e-6);
}
