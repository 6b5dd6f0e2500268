#include "camera/camera_path.hpp"

#include "io/atomic_file.hpp"
#include "io/bounded_read.hpp"
#include "io/printable.hpp"
#include "scene/load_error.hpp"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>

namespace strata {

namespace {

constexpr double kMinQuaternionLength = 1e-6;

// Shortest text that reads back to the same value (std::to_chars' round-trip guarantee).
template <class T>
std::string shortest(T value) {
    std::array<char, 64> buf{};
    auto [end, ec] = std::to_chars(buf.data(), buf.data() + buf.size(), value);
    if (ec != std::errc()) return "?";
    return std::string(buf.data(), end);
}

// At most `maxTokens` tokens are kept; `count` gets how many there are. A line of millions of
// one-character tokens is counted, not stored.
std::vector<std::string_view> splitWhitespace(std::string_view line, std::size_t maxTokens, std::size_t& count) {
    std::vector<std::string_view> tokens;
    count = 0;
    std::size_t i = 0;
    auto space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; };
    while (i < line.size()) {
        while (i < line.size() && space(line[i])) ++i;
        std::size_t start = i;
        while (i < line.size() && !space(line[i])) ++i;
        if (i > start && count++ < maxTokens) tokens.push_back(line.substr(start, i - start));
    }
    return tokens;
}

// Parses the whole token as a double; false for anything else ("1.0x", "", "--1").
bool parseNumber(std::string_view token, double& value) {
    if (!token.empty() && token.front() == '+') token.remove_prefix(1);  // from_chars rejects '+'
    auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    return ec == std::errc() && ptr == token.data() + token.size();
}

// The checks shared by read() (LoadError with file and line) and add() (invalid_argument):
// returns the problem or an empty string.
std::string checkSample(const PathSample& s, const std::vector<PathSample>& before) {
    const float* p = &s.position.x;
    bool finite = std::isfinite(s.time) && std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]) &&
                  std::isfinite(s.orientation.x) && std::isfinite(s.orientation.y) &&
                  std::isfinite(s.orientation.z) && std::isfinite(s.orientation.w);
    if (!finite) return "non-finite value";
    if (!before.empty() && s.time < before.back().time)
        return "time " + shortest(s.time) + " before previous time " + shortest(before.back().time);
    glm::dquat q(s.orientation);
    if (std::sqrt(glm::dot(q, q)) < kMinQuaternionLength) return "quaternion has zero length";
    return {};
}

glm::quat normalized(const glm::quat& q) {
    glm::dquat d(q);
    return glm::quat(d / std::sqrt(glm::dot(d, d)));
}

}  // namespace

CameraPath CameraPath::read(const std::filesystem::path& path) {
    std::string text;
    try {
        text = readBoundedFile(path, kCameraPathLimit);
    } catch (const ReadError& e) {
        throw LoadError(e.what());
    }
    return parse(text, path.string());
}

CameraPath CameraPath::parse(std::string_view text, const std::string& fileName) {
    const std::string name = printable(fileName, 120);
    CameraPath out;
    int lineNumber = 0;
    auto fail = [&](const std::string& what) {
        throw LoadError(name + ":" + std::to_string(lineNumber) + ": " + what);
    };
    while (!text.empty()) {
        ++lineNumber;
        std::size_t newline = text.find('\n');
        std::string_view view = text.substr(0, newline);
        text = newline == std::string_view::npos ? std::string_view() : text.substr(newline + 1);
        if (auto hash = view.find('#'); hash != std::string_view::npos) view = view.substr(0, hash);
        // A NUL byte (a UTF-16 file, a binary file) is no separator and no number: say so rather
        // than let it pass as part of a token or cut the message short.
        if (view.find('\0') != std::string_view::npos) fail("NUL byte: not a text file (UTF-16?)");
        std::size_t count = 0;
        auto tokens = splitWhitespace(view, 8, count);
        if (count == 0) continue;
        if (count != 8) fail("expected 8 numbers (time px py pz qx qy qz qw), got " + std::to_string(count));
        std::array<double, 8> v{};
        for (std::size_t i = 0; i < 8; ++i) {
            if (!parseNumber(tokens[i], v[i])) fail("'" + printable(tokens[i], 40) + "' is not a number");
            if (!std::isfinite(v[i])) fail("non-finite value");
        }
        // Float range is part of "finite": 1e300 metres would become inf on conversion.
        for (std::size_t i = 1; i < 8; ++i)
            if (!std::isfinite(float(v[i]))) fail("value " + shortest(v[i]) + " does not fit a float");
        PathSample s;
        s.time = v[0];
        s.position = glm::vec3(float(v[1]), float(v[2]), float(v[3]));
        s.orientation = glm::quat(float(v[7]), float(v[4]), float(v[5]), float(v[6]));  // (w, x, y, z)
        if (std::string problem = checkSample(s, out.samples_); !problem.empty()) fail(problem);
        s.orientation = normalized(s.orientation);
        out.samples_.push_back(s);
    }
    if (out.samples_.empty()) throw LoadError(name + ": no samples");
    return out;
}

void CameraPath::write(const std::filesystem::path& path) const {
    std::ostringstream out;
    out << "# strata camera path (OpenSceneGraph animation-path layout)\n"
        << "# time px py pz qx qy qz qw\n";
    for (const auto& s : samples_) {
        out << shortest(s.time) << ' ' << shortest(s.position.x) << ' ' << shortest(s.position.y) << ' '
            << shortest(s.position.z) << ' ' << shortest(s.orientation.x) << ' ' << shortest(s.orientation.y)
            << ' ' << shortest(s.orientation.z) << ' ' << shortest(s.orientation.w) << '\n';
    }
    writeTextFile(path, out.str());
}

void CameraPath::add(const PathSample& s) {
    if (std::string problem = checkSample(s, samples_); !problem.empty())
        throw std::invalid_argument("camera path sample: " + problem);
    PathSample n = s;
    n.orientation = normalized(s.orientation);
    samples_.push_back(n);
}

glm::quat slerpShortest(const glm::quat& q0, const glm::quat& q1, float u) {
    glm::dquat a(q0), b(q1);
    double cosTheta = glm::dot(a, b);
    if (cosTheta < 0.0) { b = -b; cosTheta = -cosTheta; }
    glm::dquat r;
    if (cosTheta > 0.9999995) {
        // Nearly the same rotation: sin(theta) would lose all precision; lerp is exact enough.
        r = a * (1.0 - u) + b * double(u);
    } else {
        double theta = std::acos(std::min(cosTheta, 1.0));
        double s = std::sin(theta);
        r = a * (std::sin((1.0 - u) * theta) / s) + b * (std::sin(double(u) * theta) / s);
    }
    return glm::quat(r / std::sqrt(glm::dot(r, r)));
}

PathSample CameraPath::sample(double t) const {
    if (samples_.empty()) throw std::logic_error("CameraPath::sample on an empty path");
    if (!std::isfinite(t)) throw std::invalid_argument("CameraPath::sample: time is not finite");
    // First sample strictly after t: with equal times (a cut) this makes sample() take the
    // last of them at that exact time.
    auto next = std::upper_bound(samples_.begin(), samples_.end(), t,
                                 [](double value, const PathSample& s) { return value < s.time; });
    if (next == samples_.begin()) return samples_.front();
    if (next == samples_.end()) return samples_.back();
    const PathSample& s0 = *(next - 1);
    const PathSample& s1 = *next;  // s0.time <= t < s1.time, so the span is not zero
    double u = (t - s0.time) / (s1.time - s0.time);
    PathSample out;
    out.time = t;
    out.position = glm::vec3(glm::dvec3(s0.position) + (glm::dvec3(s1.position) - glm::dvec3(s0.position)) * u);
    out.orientation = slerpShortest(s0.orientation, s1.orientation, float(u));
    return out;
}

Camera cameraAt(const CameraPath& path, double t, const Camera& base) {
    PathSample s = path.sample(t);
    Camera camera = base;
    camera.position = s.position;
    camera.orientation = s.orientation;
    return camera;
}

CameraPath orbitPath(const Bounds& bounds, int samples, double seconds, float fovYDegrees) {
    if (samples < 2) throw std::invalid_argument("orbitPath: needs at least 2 samples, got " + std::to_string(samples));
    if (!(seconds > 0.0) || !std::isfinite(seconds))
        throw std::invalid_argument("orbitPath: duration must be positive, got " + shortest(seconds));
    const glm::vec3 center = bounds.empty() ? glm::vec3(0.0f) : bounds.center();
    const float radius = bounds.empty() ? 1.0f : std::max(bounds.radius(), 1e-4f);
    // Same framing distance as frameBounds, so the orbit sees what the default camera sees.
    const double distance = radius / std::sin(glm::radians(double(fovYDegrees)) * 0.5) * 1.05;
    CameraPath path;
    glm::quat previous(1.0f, 0.0f, 0.0f, 0.0f);
    for (int i = 0; i < samples; ++i) {
        const bool last = i == samples - 1;
        const double angle = 2.0 * glm::pi<double>() * double(i) / double(samples - 1);
        Camera c;
        if (last) {
            c.position = path.samples().front().position;
            c.orientation = path.samples().front().orientation;
        } else {
            glm::dvec3 dir = glm::normalize(glm::dvec3(std::sin(angle), 0.35, std::cos(angle)));
            c.lookAt(glm::vec3(glm::dvec3(center) + dir * distance), center);
        }
        // Keep neighbours in one hemisphere so the file reads smoothly (slerp does not need it).
        glm::quat q = c.orientation;
        if (i > 0 && glm::dot(q, previous) < 0.0f) q = -q;
        previous = q;
        double time = last ? seconds : seconds * double(i) / double(samples - 1);
        path.add(time, c.position, q);
    }
    return path;
}

}  // namespace strata
