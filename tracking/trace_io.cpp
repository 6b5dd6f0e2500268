#include "tracking/trace_io.hpp"

#include "io/bounded_read.hpp"
#include "io/printable.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <limits>
#include <map>
#include <vector>

namespace strata {

// The file name is quoted like any other input: a message stays one short, printable line.
TraceError::TraceError(const std::string& file, int line, const std::string& what)
    : std::runtime_error(printable(file, 120) + ":" + std::to_string(line) + ": " + what), file_(file), line_(line) {}

}  // namespace strata

namespace strata::tracking {
namespace {

std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(" \t\r\n");
    if (b == std::string::npos) return {};
    const auto e = s.find_last_not_of(" \t\r\n");
    return s.substr(b, e - b + 1);
}

// Locale-independent and strict: the whole token must be a number.
bool parseDouble(const std::string& token, double& out) {
    const char* first = token.data();
    const char* last = token.data() + token.size();
    if (first != last && *first == '+') ++first;  // from_chars rejects a leading '+'
    const auto [ptr, ec] = std::from_chars(first, last, out);
    return ec == std::errc() && ptr == last;
}

std::vector<std::string> splitWhitespace(const std::string& line) {
    std::vector<std::string> out;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
        if (i >= line.size()) break;
        std::size_t j = i;
        while (j < line.size() && line[j] != ' ' && line[j] != '\t' && line[j] != '\r') ++j;
        out.push_back(line.substr(i, j - i));
        i = j;
    }
    return out;
}

// Counted before splitting, so that a line of millions of one-character fields is refused
// without becoming millions of strings (a 64 MiB trace could otherwise take a gigabyte).
std::size_t countWhitespaceFields(const std::string& line) {
    std::size_t n = 0;
    bool inField = false;
    for (char c : line) {
        const bool space = c == ' ' || c == '\t' || c == '\r';
        if (!space && !inField) ++n;
        inField = !space;
    }
    return n;
}

// A header names the dataset's nine columns and perhaps a few more; far more is not a trace.
constexpr std::size_t kMaxCsvColumns = 1024;

std::vector<std::string> splitComma(const std::string& line) {
    std::vector<std::string> out;
    std::size_t start = 0;
    for (;;) {
        const auto comma = line.find(',', start);
        out.push_back(trim(line.substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return out;
}

// Shared checks for one parsed sample; `previousT` is NaN for the first sample.
Eigen::Quaterniond checkedQuaternion(double x, double y, double z, double w, const std::string& name, int line) {
    Eigen::Quaterniond q(w, x, y, z);
    const double n = q.norm();
    if (n < 1e-9) throw TraceError(name, line, "quaternion is zero");
    if (std::abs(n - 1.0) > 1e-2)
        throw TraceError(name, line, "quaternion is not unit (norm " + std::to_string(n) + ")");
    q.coeffs() /= n;
    return q;
}

// A NUL byte (a UTF-16 or binary file) is neither a separator nor part of a number: name it
// rather than report a puzzling field.
void checkText(const std::string& line, const std::string& name, int lineNo) {
    if (line.find('\0') != std::string::npos) throw TraceError(name, lineNo, "NUL byte: not a text file (UTF-16?)");
}

// Positions are metres that the renderer and the metrics square and convert to float; a value
// beyond float range (1e300) would turn every error figure into inf.
void checkFloatRange(const double* v, int n, const std::string& name, int lineNo) {
    for (int i = 0; i < n; ++i)
        if (!(std::abs(v[i]) <= double(std::numeric_limits<float>::max()))) {
            char text[32];
            std::snprintf(text, sizeof text, "%g", v[i]);
            throw TraceError(name, lineNo, std::string("position ") + text + " does not fit a float");
        }
}

void checkTimeOrder(double t, double previousT, const std::string& name, int line) {
    if (!std::isnan(previousT) && t < previousT)
        throw TraceError(name, line, "time " + std::to_string(t) + " is earlier than the previous sample's " +
                                         std::to_string(previousT));
}

// Days from 1970-01-01 of a proleptic Gregorian date (Howard Hinnant's days_from_civil).
long long daysFromCivil(long long y, unsigned m, unsigned d) {
    y -= m <= 2;
    const long long era = (y >= 0 ? y : y - 399) / 400;
    const unsigned yoe = static_cast<unsigned>(y - era * 400);
    const unsigned doy = (153 * (m > 2 ? m - 3 : m + 9) + 2) / 5 + d - 1;
    const unsigned doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    return era * 146097 + static_cast<long long>(doe) - 719468;
}

}  // namespace

bool parseDateTimeSeconds(const std::string& text, double& seconds) {
    // "YYYY-MM-DD[T ]HH:MM:SS[.fff]", every field zero-padded to its width: digits only, read
    // with from_chars (no sign, no space, nothing sscanf would guess at).
    auto digits = [&](std::size_t at, std::size_t width, int& out) {
        if (text.size() < at + width) return false;
        for (std::size_t i = at; i < at + width; ++i)
            if (text[i] < '0' || text[i] > '9') return false;
        return std::from_chars(text.data() + at, text.data() + at + width, out).ptr == text.data() + at + width;
    };
    auto is = [&](std::size_t at, const char* allowed) {
        return at < text.size() && std::string_view(allowed).find(text[at]) != std::string_view::npos;
    };
    int y = 0, mo = 0, d = 0, h = 0, mi = 0;
    if (!digits(0, 4, y) || !is(4, "-") || !digits(5, 2, mo) || !is(7, "-") || !digits(8, 2, d) || !is(10, "T ") ||
        !digits(11, 2, h) || !is(13, ":") || !digits(14, 2, mi) || !is(16, ":"))
        return false;
    double sec = 0.0;
    if (!parseDouble(trim(text.substr(17)), sec)) return false;
    if (mo < 1 || mo > 12 || d < 1 || d > 31 || h < 0 || h > 23 || mi < 0 || mi > 59 || sec < 0.0 || sec >= 61.0)
        return false;
    seconds = double(daysFromCivil(y, unsigned(mo), unsigned(d))) * 86400.0 + h * 3600.0 + mi * 60.0 + sec;
    return true;
}

Trace parseAnimationPath(std::istream& in, const std::string& name) {
    Trace trace;
    std::string raw;
    int lineNo = 0;
    double previousT = std::nan("");
    while (std::getline(in, raw)) {
        ++lineNo;
        checkText(raw, name, lineNo);
        const auto hash = raw.find('#');
        const std::string line = hash == std::string::npos ? raw : raw.substr(0, hash);
        const std::size_t count = countWhitespaceFields(line);
        if (count == 0) continue;
        if (count != 8)
            throw TraceError(name, lineNo, "expected 8 fields `time px py pz qx qy qz qw`, found " + std::to_string(count));
        const auto tokens = splitWhitespace(line);
        double v[8];
        for (int i = 0; i < 8; ++i) {
            if (!parseDouble(tokens[std::size_t(i)], v[i]))
                throw TraceError(name, lineNo, "field " + std::to_string(i + 1) + " `" +
                                                   printable(tokens[std::size_t(i)], 40) + "` is not a number");
            if (!std::isfinite(v[i]))
                throw TraceError(name, lineNo, "field " + std::to_string(i + 1) + " is not finite");
        }
        checkFloatRange(v + 1, 3, name, lineNo);
        checkTimeOrder(v[0], previousT, name, lineNo);
        previousT = v[0];
        trace.push_back(PoseSample{v[0], Eigen::Vector3d(v[1], v[2], v[3]),
                                   checkedQuaternion(v[4], v[5], v[6], v[7], name, lineNo)});
    }
    if (in.bad()) throw TraceError(name, lineNo, "read error");
    return trace;
}

namespace {

// The whole trace file, within kTraceLimit (io/bounded_read.hpp), as a stream for the parsers.
std::istringstream openTrace(const std::string& path) {
    try {
        return std::istringstream(readBoundedFile(path, kTraceLimit));
    } catch (const ReadError& e) {
        throw TraceError(e.what());
    }
}

}  // namespace

Trace readAnimationPath(const std::string& path) {
    std::istringstream f = openTrace(path);
    return parseAnimationPath(f, path);
}

std::string formatAnimationPath(const Trace& trace, const std::string& comment) {
    std::string out = "# strata animation path: time px py pz qx qy qz qw (s, m, unit quaternion)\n";
    if (!comment.empty()) {
        std::size_t start = 0;
        while (start <= comment.size()) {
            const auto nl = comment.find('\n', start);
            out += "# " + comment.substr(start, nl == std::string::npos ? std::string::npos : nl - start) + "\n";
            if (nl == std::string::npos) break;
            start = nl + 1;
        }
    }
    for (const auto& s : trace) {
        // Sized by a first call: %f of a large coordinate has no length bound.
        auto print = [&](char* to, std::size_t n) {
            return std::snprintf(to, n, "%.6f %.6f %.6f %.6f %.9f %.9f %.9f %.9f\n", s.t, s.p.x(), s.p.y(), s.p.z(),
                                 s.q.x(), s.q.y(), s.q.z(), s.q.w());
        };
        std::size_t at = out.size(), n = std::size_t(print(nullptr, 0));
        out.resize(at + n + 1);
        print(out.data() + at, n + 1);
        out.resize(at + n);
    }
    return out;
}

Trace parseHeadMovementCsv(std::istream& in, const std::string& name) {
    static const char* const kColumns[] = {"Timestamp",        "UnitQuaternion.x", "UnitQuaternion.y",
                                           "UnitQuaternion.z", "UnitQuaternion.w", "HmdPosition.x",
                                           "HmdPosition.y",    "HmdPosition.z"};
    std::string raw;
    int lineNo = 0;
    std::size_t index[8];
    std::size_t columnCount = 0;
    bool haveHeader = false;
    Trace trace;
    double firstT = 0.0, previousT = std::nan("");
    while (std::getline(in, raw)) {
        ++lineNo;
        checkText(raw, name, lineNo);
        std::string line = trim(raw);
        // A UTF-8 byte-order mark before the header: .NET's StreamWriter (Unity's logger) writes
        // one by default, and it would otherwise become part of the first column's name.
        if (!haveHeader && line.rfind("\xEF\xBB\xBF", 0) == 0) line = trim(line.substr(3));
        if (line.empty()) continue;
        const std::size_t count = std::size_t(std::count(line.begin(), line.end(), ',')) + 1;
        if (!haveHeader && count > kMaxCsvColumns)
            throw TraceError(name, lineNo, "header has " + std::to_string(count) + " columns, more than " +
                                               std::to_string(kMaxCsvColumns));
        if (haveHeader && count != columnCount)
            throw TraceError(name, lineNo, "expected " + std::to_string(columnCount) + " comma-separated fields, found " +
                                               std::to_string(count));
        const auto fields = splitComma(line);
        if (!haveHeader) {
            std::map<std::string, std::size_t> byName;
            for (std::size_t i = 0; i < fields.size(); ++i) byName[fields[i]] = i;
            for (int c = 0; c < 8; ++c) {
                const auto it = byName.find(kColumns[c]);
                if (it == byName.end())
                    throw TraceError(name, lineNo, std::string("header lacks column `") + kColumns[c] + "`");
                index[c] = it->second;
            }
            columnCount = fields.size();
            haveHeader = true;
            continue;
        }
        double t = 0.0;
        const std::string& ts = fields[index[0]];
        if (!parseDouble(ts, t) && !parseDateTimeSeconds(ts, t))
            throw TraceError(name, lineNo, "Timestamp `" + printable(ts, 40) + "` is neither seconds nor YYYY-MM-DD HH:MM:SS.fff");
        double v[7];
        for (int c = 1; c < 8; ++c) {
            const std::string& f = fields[index[c]];
            if (!parseDouble(f, v[c - 1]) || !std::isfinite(v[c - 1]))
                throw TraceError(name, lineNo, std::string(kColumns[c]) + " `" + printable(f, 40) + "` is not a finite number");
        }
        checkFloatRange(v + 4, 3, name, lineNo);
        if (!std::isfinite(t)) throw TraceError(name, lineNo, "Timestamp is not finite");
        if (trace.empty()) firstT = t;
        t -= firstT;
        checkTimeOrder(t, previousT, name, lineNo);
        previousT = t;
        // Unity (left-handed, +Z forward) -> right-handed, -Z forward: mirror Z (see header).
        const Eigen::Quaterniond q = checkedQuaternion(-v[0], -v[1], v[2], v[3], name, lineNo);
        trace.push_back(PoseSample{t, Eigen::Vector3d(v[4], v[5], -v[6]), q});
    }
    if (in.bad()) throw TraceError(name, lineNo, "read error");
    if (!haveHeader) throw TraceError(name, lineNo, "no header line");
    return trace;
}

Trace readHeadMovementCsv(const std::string& path) {
    std::istringstream f = openTrace(path);
    return parseHeadMovementCsv(f, path);
}

Trace readTrace(const std::string& path) {
    const bool csv = path.size() >= 4 && (path.compare(path.size() - 4, 4, ".csv") == 0 ||
                                         path.compare(path.size() - 4, 4, ".CSV") == 0);
    return csv ? readHeadMovementCsv(path) : readAnimationPath(path);
}

}  // namespace strata::tracking
