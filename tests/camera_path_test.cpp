// Camera paths: the OSG animation-path text layout, interpolation and the errors bad files give.
#include "camera/camera_path.hpp"
#include "scene/load_error.hpp"

#include <doctest/doctest.h>
#include <glm/gtc/constants.hpp>

#include <filesystem>
#include <iterator>
#include <fstream>
#include <string>
#include <unistd.h>

using namespace strata;

namespace {

// A private scratch folder per test process, removed at the end of each test.
struct TempDir {
    std::filesystem::path dir;
    TempDir() {
        dir = std::filesystem::temp_directory_path() / ("strata_camera_path_" + std::to_string(::getpid()));
        std::filesystem::create_directories(dir);
    }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::remove_all(dir, ec);
    }
    std::filesystem::path file(const std::string& name, const std::string& text) const {
        std::filesystem::path p = dir / name;
        std::ofstream(p, std::ios::binary) << text;
        return p;
    }
};

glm::quat axisAngle(float degrees, glm::vec3 axis) { return glm::angleAxis(glm::radians(degrees), glm::normalize(axis)); }

// The rotation angle between two orientations, in degrees (q and -q are the same rotation).
double angleBetween(const glm::quat& a, const glm::quat& b) {
    double d = std::min(1.0, std::abs(double(glm::dot(glm::normalize(a), glm::normalize(b)))));
    return glm::degrees(2.0 * std::acos(d));
}

std::string errorOf(const std::filesystem::path& p) {
    try {
        CameraPath::read(p);
    } catch (const LoadError& e) {
        return e.what();
    }
    return "(no error)";
}

}  // namespace

TEST_CASE("camera path: write then read gives the same samples bit for bit") {
    TempDir tmp;
    CameraPath path;
    path.add(0.0, {1.0f, 2.0f, 3.0f}, glm::quat(1, 0, 0, 0));
    path.add(0.1, {0.1f, -1e-7f, 12345.678f}, axisAngle(33.3f, {1, 2, 3}));
    path.add(1.0 / 3.0, {-4.0f, 5.5f, 6.25f}, axisAngle(-170.0f, {0, 1, 0}));
    path.add(1.0 / 3.0, {7.0f, 8.0f, 9.0f}, axisAngle(10.0f, {0, 0, 1}));  // a cut
    auto file = tmp.dir / "path.txt";
    path.write(file);
    // Only the file itself: no temporary of any name is left beside it.
    CHECK(std::distance(std::filesystem::directory_iterator(tmp.dir), std::filesystem::directory_iterator()) == 1);
    CameraPath back = CameraPath::read(file);
    REQUIRE(back.samples().size() == path.samples().size());
    for (std::size_t i = 0; i < path.samples().size(); ++i) {
        CAPTURE(i);
        const auto& a = path.samples()[i];
        const auto& b = back.samples()[i];
        CHECK(a.time == b.time);
        CHECK(a.position == b.position);
        // Re-normalising an already unit quaternion may move the last bit; the rotation is the same.
        CHECK(angleBetween(a.orientation, b.orientation) < 1e-3);
    }
    CHECK(back.duration() == doctest::Approx(1.0 / 3.0));
}

TEST_CASE("camera path: comments, blank lines, CRLF, '+' signs and unnormalised quaternions") {
    TempDir tmp;
    auto file = tmp.file("c.path",
                         "# an OSG animation path\n"
                         "\n"
                         "   \t\n"
                         "0 0 0 0   0 0 0 2   # identity, length 2\r\n"
                         "# mid comment\n"
                         "+2.5 1e1 -2 +3 0 0 0 1\n");
    CameraPath p = CameraPath::read(file);
    REQUIRE(p.samples().size() == 2);
    CHECK(p.samples()[0].orientation.w == 1.0f);
    CHECK(p.samples()[1].time == 2.5);
    CHECK(p.samples()[1].position == glm::vec3(10.0f, -2.0f, 3.0f));
    CHECK(p.duration() == 2.5);
}

TEST_CASE("camera path: interpolation") {
    CameraPath p;
    p.add(1.0, {0, 0, 0}, glm::quat(1, 0, 0, 0));
    p.add(3.0, {2, 4, -6}, axisAngle(90.0f, {0, 1, 0}));
    SUBCASE("midpoint lerps position and slerps 90 degrees to 45") {
        PathSample s = p.sample(2.0);
        CHECK(s.position.x == doctest::Approx(1.0));
        CHECK(s.position.y == doctest::Approx(2.0));
        CHECK(s.position.z == doctest::Approx(-3.0));
        CHECK(angleBetween(s.orientation, axisAngle(45.0f, {0, 1, 0})) < 1e-3);
        CHECK(glm::length(s.orientation) == doctest::Approx(1.0));
    }
    SUBCASE("quarter point is a quarter of the angle (constant angular speed)") {
        CHECK(angleBetween(p.sample(1.5).orientation, axisAngle(22.5f, {0, 1, 0})) < 1e-3);
    }
    SUBCASE("clamped outside the range") {
        CHECK(p.sample(-10.0).position == glm::vec3(0.0f));
        CHECK(p.sample(1e9).position == glm::vec3(2, 4, -6));
        CHECK(p.sample(3.0).position == glm::vec3(2, 4, -6));
    }
    SUBCASE("the camera helper keeps the base's lens") {
        Camera base;
        base.fovYDegrees = 33.0f;
        base.nearPlane = 0.5f;
        base.farPlane = 70.0f;
        Camera c = cameraAt(p, 2.0, base);
        CHECK(c.fovYDegrees == 33.0f);
        CHECK(c.nearPlane == 0.5f);
        CHECK(c.farPlane == 70.0f);
        CHECK(c.position.y == doctest::Approx(2.0));
        // Turning 45 degrees about +Y from looking down -Z looks down (-1, 0, -1) / sqrt 2.
        CHECK(c.forward().x == doctest::Approx(-std::sqrt(0.5)).epsilon(1e-5));
        CHECK(c.forward().z == doctest::Approx(-std::sqrt(0.5)).epsilon(1e-5));
    }
}

TEST_CASE("camera path: antipodal quaternions take the short way") {
    // q and -q are the same rotation: a file may flip sign between samples. The path between
    // a 10 and a 30 degree turn must stay between them, not swing through 200 degrees.
    CameraPath p;
    p.add(0.0, {0, 0, 0}, axisAngle(10.0f, {1, 0, 0}));
    p.add(1.0, {0, 0, 0}, -axisAngle(30.0f, {1, 0, 0}));
    CHECK(angleBetween(p.sample(0.5).orientation, axisAngle(20.0f, {1, 0, 0})) < 1e-3);
    // The same rotation with both signs interpolates to itself.
    glm::quat q = axisAngle(77.0f, {1, 1, 0});
    CHECK(angleBetween(slerpShortest(q, -q, 0.5f), q) < 1e-3);
}

TEST_CASE("camera path: equal times are a cut, taken at the later sample") {
    CameraPath p;
    p.add(0.0, {0, 0, 0}, glm::quat(1, 0, 0, 0));
    p.add(1.0, {1, 0, 0}, glm::quat(1, 0, 0, 0));
    p.add(1.0, {5, 0, 0}, glm::quat(1, 0, 0, 0));
    p.add(2.0, {6, 0, 0}, glm::quat(1, 0, 0, 0));
    CHECK(p.sample(0.999999).position.x == doctest::Approx(1.0).epsilon(1e-5));
    CHECK(p.sample(1.0).position.x == 5.0f);
    CHECK(p.sample(1.5).position.x == doctest::Approx(5.5));
    CHECK_THROWS_AS(p.add(1.5, {0, 0, 0}, glm::quat(1, 0, 0, 0)), std::invalid_argument);
    CHECK_THROWS_AS(p.add(3.0, {0, 0, 0}, glm::quat(0, 0, 0, 0)), std::invalid_argument);
}

TEST_CASE("camera path: malformed input names the file and line") {
    TempDir tmp;
    const std::string good = "0 0 0 0 0 0 0 1\n";
    struct Case {
        const char* name;
        std::string text;
        std::string message;  // after "FILE"
    };
    const Case cases[] = {
        {"short.txt", good + "# c\n1 2 3 4 5\n", ":3: expected 8 numbers (time px py pz qx qy qz qw), got 5"},
        {"long.txt", good + "1 0 0 0 0 0 0 1 9\n", ":2: expected 8 numbers (time px py pz qx qy qz qw), got 9"},
        {"word.txt", "\n\n0 0 abc 0 0 0 0 1\n", ":3: 'abc' is not a number"},
        {"suffix.txt", "0 0 1.5x 0 0 0 0 1\n", ":1: '1.5x' is not a number"},
        // A line of a million tokens is counted, not stored.
        {"many.txt", [] { std::string s; for (int i = 0; i < 1000000; ++i) s += "1 "; return s; }(),
         ":1: expected 8 numbers (time px py pz qx qy qz qw), got 1000000"},
        // A 10 MB token is quoted as its first 40 characters; control bytes are escaped.
        {"token.txt", "0 0 " + std::string(10 << 20, '9') + "x 0 0 0 0 1\n", ":1: '" + std::string(40, '9') + "...' is not a number"},
        {"escape.txt", "0 0 \x1b[2J 0 0 0 0 1\n", ":1: '\\x1B[2J' is not a number"},
        // UTF-16 (what a Windows editor may save): named as such, not cut at the first NUL.
        {"utf16.txt", std::string("\xff\xfe" "0\0 \0" "0\0", 8), ":1: NUL byte: not a text file (UTF-16?)"},
        {"nan.txt", good + "1 nan 0 0 0 0 0 1\n", ":2: non-finite value"},
        {"inf.txt", "inf 0 0 0 0 0 0 1\n", ":1: non-finite value"},
        {"huge.txt", "0 1e300 0 0 0 0 0 1\n", ":1: value 1e+300 does not fit a float"},
        {"order.txt", "2.0 0 0 0 0 0 0 1\n1.5 0 0 0 0 0 0 1\n", ":2: time 1.5 before previous time 2"},
        {"zeroq.txt", good + "1 0 0 0 0 0 0 0\n", ":2: quaternion has zero length"},
        {"tinyq.txt", "0 0 0 0 1e-9 0 0 1e-9\n", ":1: quaternion has zero length"},
        {"empty.txt", "", ": no samples"},
        {"comments.txt", "# nothing\n\n   \n", ": no samples"},
    };
    for (const auto& c : cases) {
        CAPTURE(c.name);
        auto file = tmp.file(c.name, c.text);
        CHECK(errorOf(file) == file.string() + c.message);
    }
    auto missing = tmp.dir / "missing.txt";
    CHECK(errorOf(missing) == missing.string() + ": no such file");
}

TEST_CASE("camera path: a failed write leaves nothing behind") {
    TempDir tmp;
    CameraPath p;
    p.add(0.0, {0, 0, 0}, glm::quat(1, 0, 0, 0));
    auto file = tmp.dir / "no_such_dir" / "p.txt";
    CHECK_THROWS_AS(p.write(file), std::runtime_error);
    CHECK_FALSE(std::filesystem::exists(file));
    CHECK_THROWS_AS(CameraPath().sample(0.0), std::logic_error);
}

TEST_CASE("camera path: orbit around bounds") {
    Bounds b;
    b.extend(glm::vec3(-1.0f, 0.0f, 2.0f));
    b.extend(glm::vec3(3.0f, 2.0f, 4.0f));
    CameraPath orbit = orbitPath(b, 33, 8.0);
    REQUIRE(orbit.samples().size() == 33);
    CHECK(orbit.duration() == 8.0);
    CHECK(orbit.samples().front().position == orbit.samples().back().position);
    CHECK(angleBetween(orbit.samples().front().orientation, orbit.samples().back().orientation) < 1e-3);
    double distance = glm::length(orbit.samples()[0].position - b.center());
    Camera base;
    for (double t : {0.0, 0.37, 2.0, 5.55, 8.0}) {
        CAPTURE(t);
        Camera c = cameraAt(orbit, t, base);
        glm::vec3 toCenter = glm::normalize(b.center() - c.position);
        // Between samples the slerped view drifts a little off the centre; 11.25 degree steps
        // keep it within a degree.
        CHECK(glm::dot(c.forward(), toCenter) > std::cos(glm::radians(1.0f)));
        CHECK(glm::length(c.position - b.center()) == doctest::Approx(distance).epsilon(0.01));
    }
    CHECK_THROWS_AS(orbitPath(b, 1, 1.0), std::invalid_argument);
    CHECK_THROWS_AS(orbitPath(b, 8, 0.0), std::invalid_argument);
}
