#pragma once
// Camera paths in OpenSceneGraph's animation-path text layout, shared with head-pose traces:
//
//     # comment (also after a sample)
//     time px py pz qx qy qz qw
//
// seconds, metres, and the camera's orientation as a quaternion (x y z w order, as OSG writes
// it) with the camera looking down its local -Z, +Y up (the Camera convention).
//
// Rules (a violation throws strata::LoadError with one line "FILE:LINE: what is wrong"):
//  - exactly 8 numbers per sample line, all finite;
//  - times are non-decreasing. Equal times are allowed and mean a cut: the path jumps, and
//    sample(t) at that time returns the last sample with that time (right-continuous), so a
//    path can teleport between shots without a blend. Strictly decreasing times are an error;
//  - quaternions are normalised on reading; one shorter than 1e-6 is an error;
//  - a file without samples is an error ("FILE: no samples").
#include "camera/camera.hpp"
#include "scene/scene.hpp"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace strata {

struct PathSample {
    double time = 0.0;
    glm::vec3 position{0.0f};
    glm::quat orientation{1.0f, 0.0f, 0.0f, 0.0f};
};

class CameraPath {
public:
    // Throws LoadError (bad content, missing file) naming the file and, for content, the line.
    // The file is read through readBoundedFile (io/bounded_read.hpp): a regular file of at most
    // kCameraPathLimit bytes.
    static CameraPath read(const std::filesystem::path& path);
    // The same from text already in memory; `fileName` names it in messages.
    static CameraPath parse(std::string_view text, const std::string& fileName);
    // Writes every sample with round-trip precision through writeTextFile (io/atomic_file.hpp),
    // so a failure leaves nothing half-written. Throws std::runtime_error naming the file.
    void write(const std::filesystem::path& path) const;

    // Position lerped, orientation slerped along the shorter arc; clamped to the first/last
    // sample outside the time range. Throws std::logic_error on an empty path.
    PathSample sample(double t) const;

    // Appends a sample. Throws std::invalid_argument when its time is before the last one, a
    // value is not finite or the quaternion has (near) zero length; normalises the quaternion.
    void add(const PathSample& s);
    void add(double time, const glm::vec3& position, const glm::quat& orientation) { add({time, position, orientation}); }

    const std::vector<PathSample>& samples() const { return samples_; }
    bool empty() const { return samples_.empty(); }
    double startTime() const { return samples_.empty() ? 0.0 : samples_.front().time; }
    double endTime() const { return samples_.empty() ? 0.0 : samples_.back().time; }
    double duration() const { return endTime() - startTime(); }

private:
    std::vector<PathSample> samples_;
};

// Spherical interpolation along the shorter arc (q1 negated when dot(q0, q1) < 0, as q and -q
// are the same rotation); falls back to normalised lerp when the two are nearly equal.
glm::quat slerpShortest(const glm::quat& q0, const glm::quat& q1, float u);

// `base` with the path's pose at time t (field of view and clip planes come from `base`).
Camera cameraAt(const CameraPath& path, double t, const Camera& base);

// A full circle around `bounds` at the distance that frames it for `fovYDegrees`, slightly
// above its centre and looking at it: `samples` (>= 2) samples over `seconds` (> 0), the last
// equal to the first so the loop is closed. Used by the bench for a repeatable camera motion.
CameraPath orbitPath(const Bounds& bounds, int samples, double seconds, float fovYDegrees = 50.0f);

}  // namespace strata
