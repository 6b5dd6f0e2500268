#pragma once
// Poses, traces and the rotation helpers every predictor shares.
//
// Conventions (the same as core/camera): a pose is the head (camera) frame expressed in world
// coordinates; q rotates camera-local vectors into the world; the camera looks along local -Z
// with +Y up and +X right. Time in seconds, position in metres.
//
// Rotation vectors are used wherever a quantity is "a small rotation" (errors, angular
// velocity times dt). Quaternion components are never filtered or differenced directly: they
// live on a sphere with q ~ -q, so component arithmetic is wrong away from the identity.
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <vector>

namespace strata::tracking {

struct PoseSample {
    double t = 0.0;
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
};

// Samples in non-decreasing time (readers enforce it). Duplicate times are allowed.
using Trace = std::vector<PoseSample>;

// Exp: rotation vector (axis * angle, radians) -> unit quaternion. Stable at zero (Taylor).
Eigen::Quaterniond quatExp(const Eigen::Vector3d& rotationVector);
// Log: unit quaternion -> rotation vector with angle in [0, pi]. q and -q give the same
// result (the shorter way round is taken), so sign flips in a stream are harmless.
Eigen::Vector3d quatLog(const Eigen::Quaterniond& q);
// Geodesic angle between two orientations, radians in [0, pi]; sign-insensitive.
double angleBetween(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b);
inline double radToDeg(double r) { return r * 57.295779513082320876798; }
inline double degToRad(double d) { return d * 0.017453292519943295769237; }
// Rotation vector of b relative to a in the world frame: b = quatExp(v) * a.
Eigen::Vector3d worldDelta(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b);
// Slerp that also extrapolates (s outside [0, 1]) along the shorter arc: a -> b at s = 1.
Eigen::Quaterniond slerpExtrapolate(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b,
                                    double s);
// Skew-symmetric cross-product matrix: skew(a) * b == a.cross(b).
Eigen::Matrix3d skew(const Eigen::Vector3d& v);
// Normalises, and returns identity for a zero or non-finite quaternion instead of NaN.
Eigen::Quaterniond safeNormalized(const Eigen::Quaterniond& q);

// Pose on the trace at time t: linear in position, slerp in orientation between the
// bracketing samples; clamped to the first/last sample outside the trace. Empty -> identity.
PoseSample sampleAt(const Trace& trace, double t);

// Bridges to the viewer's glm camera (float).
inline glm::quat toGlm(const Eigen::Quaterniond& q) {
    return glm::quat(float(q.w()), float(q.x()), float(q.y()), float(q.z()));
}
inline glm::vec3 toGlm(const Eigen::Vector3d& v) { return glm::vec3(float(v.x()), float(v.y()), float(v.z())); }
inline Eigen::Quaterniond toEigen(const glm::quat& q) { return Eigen::Quaterniond(q.w, q.x, q.y, q.z); }
// Column-major glm from Eigen, in double (homographies are inverted before going to float).
inline glm::dmat3 toGlm(const Eigen::Matrix3d& m) {
    glm::dmat3 g;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) g[c][r] = m(r, c);
    return g;
}

}  // namespace strata::tracking
