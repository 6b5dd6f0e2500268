#pragma once
// Reading and writing head-pose traces.
//
// Animation-path text (DESIGN.md "Paths and traces", OpenSceneGraph's AnimationPath layout):
// one sample a line, `time px py pz qx qy qz qw` (seconds, metres, unit quaternion); `#` starts
// a comment (whole line or trailing); blank lines are skipped. A line with the wrong number of
// fields, a non-number, a non-finite value, a zero quaternion or one whose norm is off by more
// than 1e-2 (beyond print rounding), or a time earlier than the line before is an error.
// Quaternions within tolerance are renormalised.
//
// Head-movement CSV of Wu et al., "A Dataset for Exploring User Behaviors in VR Spherical
// Video Streaming" (MMSys 2017): a header line naming the columns, located by name so extra
// or reordered columns are fine: Timestamp, PlaybackTime, UnitQuaternion.x, .y, .z, .w,
// HmdPosition.x, .y, .z. Timestamp is either a number of seconds or a date-time string
// `YYYY-MM-DD HH:MM:SS[.fff...]` (also with a `T` separator); both are made relative to the
// first sample, so traces start at t = 0. A UTF-8 byte-order mark before the header and CRLF
// line ends (both what the dataset's .NET logger writes) are accepted. The dataset was recorded in Unity (left-handed,
// +Z forward); samples are converted to this project's right-handed, -Z-forward frame by
// mirroring Z: p = (x, y, -z), q = (-qx, -qy, qz, qw).
//
// Files are read through readBoundedFile (io/bounded_read.hpp): a regular file of at most
// kTraceLimit bytes, else `file: problem` naming the limit and the size. A NUL byte (UTF-16) and
// a position beyond float range are errors of their line.
//
// Every failure throws strata::TraceError whose what() is one line: `file:line: problem`.
#include "tracking/pose.hpp"

#include <istream>
#include <stdexcept>
#include <string>

namespace strata {

// A malformed or unreadable trace. Kept in tracking (not shared with strata_core's errors)
// so this library stays free of GL and core dependencies.
class TraceError : public std::runtime_error {
public:
    TraceError(const std::string& file, int line, const std::string& what);
    explicit TraceError(const std::string& message) : std::runtime_error(message) {}
    const std::string& file() const { return file_; }
    int line() const { return line_; }

private:
    std::string file_;
    int line_ = 0;
};

}  // namespace strata

namespace strata::tracking {

using strata::TraceError;

// `name` is used in error messages only.
Trace parseAnimationPath(std::istream& in, const std::string& name);
Trace readAnimationPath(const std::string& path);
// The text of an animation-path file: a header comment (each line of `comment` as one more
// comment line), then one sample a line (microsecond time, micrometre position, 1e-9
// quaternion). Writing it is the caller's: this library does no file output, so the one
// atomic writer (strata_core's io/atomic_file.hpp) stays the only one.
std::string formatAnimationPath(const Trace& trace, const std::string& comment = {});

Trace parseHeadMovementCsv(std::istream& in, const std::string& name);
Trace readHeadMovementCsv(const std::string& path);

// Picks the reader by extension: .csv -> head-movement CSV, anything else -> animation path.
Trace readTrace(const std::string& path);

// Seconds since 1970-01-01 of a `YYYY-MM-DD HH:MM:SS[.fff]` string (no time zone: only
// differences are used). Returns false when the text is not in that form.
bool parseDateTimeSeconds(const std::string& text, double& seconds);

}  // namespace strata::tracking
