#include "tracking/deflection.hpp"

#include <cmath>
#include <stdexcept>

namespace strata::tracking {
namespace {

// GL camera frame (x right, y up, looking down -z) -> pixel frame (x right, y down, z forward).
const Eigen::Matrix3d& glToPixelFrame() {
    static const Eigen::Matrix3d c = Eigen::Vector3d(1.0, -1.0, -1.0).asDiagonal();
    return c;
}

}  // namespace

Intrinsics Intrinsics::fromFov(int width, int height, double horizontalFovDeg) {
    Intrinsics k;
    k.width = width;
    k.height = height;
    k.fx = k.fy = 0.5 * width / std::tan(0.5 * degToRad(horizontalFovDeg));
    k.cx = 0.5 * width;
    k.cy = 0.5 * height;
    return k;
}

Intrinsics Intrinsics::fromFovY(int width, int height, double verticalFovDeg) {
    double horizontal = 2.0 * std::atan(std::tan(0.5 * degToRad(verticalFovDeg)) * double(width) / double(height));
    return fromFov(width, height, horizontal * 180.0 / 3.14159265358979323846);
}

Eigen::Matrix3d Intrinsics::K() const {
    Eigen::Matrix3d m;
    m << fx, 0.0, cx, 0.0, fy, cy, 0.0, 0.0, 1.0;
    return m;
}

std::string_view deflectName(Deflect d) {
    switch (d) {
        case Deflect::None: return "none";
        case Deflect::Shift: return "shift";
        case Deflect::Homography: return "homography";
    }
    return "none";
}

Deflect parseDeflect(std::string_view name) {
    if (name == "none") return Deflect::None;
    if (name == "shift") return Deflect::Shift;
    if (name == "homography") return Deflect::Homography;
    throw std::invalid_argument("unknown deflection `" + std::string(name) + "` (known: none, shift, homography)");
}

bool projectDirection(const Intrinsics& k, const Eigen::Quaterniond& q, const Eigen::Vector3d& worldDir,
                      Eigen::Vector2d& pixel) {
    const Eigen::Vector3d c = glToPixelFrame() * (q.conjugate() * worldDir);
    if (c.z() <= 0.0) return false;
    pixel = Eigen::Vector2d(k.fx * c.x() / c.z() + k.cx, k.fy * c.y() / c.z() + k.cy);
    return true;
}

Eigen::Vector3d unprojectPixel(const Intrinsics& k, const Eigen::Quaterniond& q, const Eigen::Vector2d& pixel) {
    const Eigen::Vector3d c((pixel.x() - k.cx) / k.fx, (pixel.y() - k.cy) / k.fy, 1.0);
    return (q * (glToPixelFrame() * c)).normalized();
}

Eigen::Vector2d deflectionShift(const Intrinsics& k, const Eigen::Quaterniond& rendered,
                                const Eigen::Quaterniond& latest) {
    // Rotation from the rendered to the latest view in the rendered camera's frame (R1^T R2);
    // its rotation vector's Y is yaw (turning left moves content right), X is pitch (looking
    // up moves content down in a y-down image).
    const Eigen::Vector3d phi = quatLog(rendered.conjugate() * latest);
    return Eigen::Vector2d(k.fx * phi.y(), k.fy * phi.x());
}

Eigen::Matrix3d deflectionHomography(const Intrinsics& k, const Eigen::Quaterniond& rendered,
                                     const Eigen::Quaterniond& latest) {
    const Eigen::Matrix3d& c = glToPixelFrame();
    const Eigen::Matrix3d rel = c * (latest.conjugate() * rendered).toRotationMatrix() * c;
    const Eigen::Matrix3d kk = k.K();
    return kk * rel * kk.inverse();
}

Eigen::Vector2d applyHomography(const Eigen::Matrix3d& h, const Eigen::Vector2d& pixel) {
    const Eigen::Vector3d v = h * pixel.homogeneous();
    return v.hnormalized();
}

}  // namespace strata::tracking
