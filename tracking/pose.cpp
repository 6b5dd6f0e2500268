#include "tracking/pose.hpp"

#include <algorithm>
#include <cmath>

namespace strata::tracking {

Eigen::Quaterniond quatExp(const Eigen::Vector3d& v) {
    const double angle = v.norm();
    const double half = 0.5 * angle;
    // sin(x/2)/x via Taylor below 1e-4 rad: the direct quotient loses all digits near zero.
    const double k = angle < 1e-4 ? 0.5 - angle * angle / 48.0 : std::sin(half) / angle;
    Eigen::Quaterniond q(std::cos(half), k * v.x(), k * v.y(), k * v.z());
    return q.normalized();
}

Eigen::Vector3d quatLog(const Eigen::Quaterniond& qIn) {
    Eigen::Quaterniond q = qIn;
    if (q.w() < 0.0) q.coeffs() = -q.coeffs();  // shorter arc: q and -q are one rotation
    const double s = q.vec().norm();
    // atan2 is accurate at both ends (s -> 0 and w -> 0), unlike acos(w) near the identity.
    const double angle = 2.0 * std::atan2(s, q.w());
    if (s < 1e-12) return 2.0 * q.vec() / std::max(q.w(), 1e-300);
    return q.vec() * (angle / s);
}

double angleBetween(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
    return quatLog(b * a.conjugate()).norm();
}

Eigen::Vector3d worldDelta(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
    return quatLog(b * a.conjugate());
}

Eigen::Quaterniond slerpExtrapolate(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b,
                                    double s) {
    return safeNormalized(quatExp(s * worldDelta(a, b)) * a);
}

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
    Eigen::Matrix3d m;
    m << 0.0, -v.z(), v.y(),
         v.z(), 0.0, -v.x(),
         -v.y(), v.x(), 0.0;
    return m;
}

Eigen::Quaterniond safeNormalized(const Eigen::Quaterniond& q) {
    const double n = q.norm();
    if (!(n > 1e-300) || !std::isfinite(n)) return Eigen::Quaterniond::Identity();
    Eigen::Quaterniond r = q;
    r.coeffs() /= n;
    return r;
}

PoseSample sampleAt(const Trace& trace, double t) {
    if (trace.empty()) return PoseSample{t, Eigen::Vector3d::Zero(), Eigen::Quaterniond::Identity()};
    if (t <= trace.front().t) return PoseSample{t, trace.front().p, trace.front().q};
    if (t >= trace.back().t) return PoseSample{t, trace.back().p, trace.back().q};
    auto hi = std::upper_bound(trace.begin(), trace.end(), t,
                               [](double x, const PoseSample& s) { return x < s.t; });
    const PoseSample& b = *hi;
    const PoseSample& a = *(hi - 1);
    const double span = b.t - a.t;
    const double s = span > 0.0 ? (t - a.t) / span : 1.0;
    return PoseSample{t, a.p + s * (b.p - a.p), slerpExtrapolate(a.q, b.q, s)};
}

}  // namespace strata::tracking
