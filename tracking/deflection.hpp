#pragma once
// Image deflection (Mazuryk & Gervautz, "Two-step prediction and image deflection", 1995):
// after rendering with the pose predicted at frame start, the tracker is read again and the
// finished image is moved to fit the newer prediction. This file holds the CPU math only; the
// GL warp that applies it to a frame is core/render/deflection_warp.hpp (tracking has no GL);
// it converts from this file's y-down forward map to GL's y-up inverse map.
//
// Pixel convention: x right, y down, origin at the top-left pixel corner; pinhole intrinsics
// K = [fx 0 cx; 0 fy cy; 0 0 1] act on the camera frame C = diag(1, -1, -1) * (GL camera
// frame), i.e. right, down, forward. A world direction d shows at pixel ~ K C R^T d for a
// camera with orientation R (camera -> world, as in core/camera).
//
// Deflections, from the rendered orientation R1 to the re-predicted orientation R2:
//  - homography: x2 ~ H x1 with H = K (C R2^T R1 C) K^-1. Exact for a pure rotation (content
//    at infinity or a pure head rotation): the warped image equals the image rendered at R2.
//    It cannot correct translation (parallax needs depth).
//  - shift: the paper's pan and scroll, a 2D translation by (fx * yaw, fy * pitch) where
//    (pitch, yaw) are the X and Y components of the rotation vector of R1^T R2 (camera frame:
//    +X right, +Y up). First-order in the rotation at the principal point; it ignores roll and
//    the growth of the image motion towards the edges (1/cos^2 of the off-axis angle).
#include "tracking/pose.hpp"

#include <string>
#include <string_view>

namespace strata::tracking {

struct Intrinsics {
    double fx = 1.0, fy = 1.0, cx = 0.0, cy = 0.0;
    int width = 1, height = 1;
    // Square pixels, principal point at the centre, horizontal field of view in degrees.
    static Intrinsics fromFov(int width, int height, double horizontalFovDeg);
    // The same from the vertical field of view, as strata's Camera states it.
    static Intrinsics fromFovY(int width, int height, double verticalFovDeg);
    Eigen::Matrix3d K() const;
};

enum class Deflect { None, Shift, Homography };
std::string_view deflectName(Deflect d);
// Throws std::invalid_argument for anything but none, shift, homography.
Deflect parseDeflect(std::string_view name);

// Pixel of a world direction seen by a camera with orientation q; false when behind it.
bool projectDirection(const Intrinsics& k, const Eigen::Quaterniond& q, const Eigen::Vector3d& worldDir,
                      Eigen::Vector2d& pixel);
// Unit world direction through a pixel.
Eigen::Vector3d unprojectPixel(const Intrinsics& k, const Eigen::Quaterniond& q, const Eigen::Vector2d& pixel);

// 2D shift in pixels that moves the image rendered at `rendered` towards `latest`.
Eigen::Vector2d deflectionShift(const Intrinsics& k, const Eigen::Quaterniond& rendered,
                                const Eigen::Quaterniond& latest);
// 3x3 homography mapping rendered-image pixels to latest-image pixels (homogeneous).
Eigen::Matrix3d deflectionHomography(const Intrinsics& k, const Eigen::Quaterniond& rendered,
                                     const Eigen::Quaterniond& latest);
Eigen::Vector2d applyHomography(const Eigen::Matrix3d& h, const Eigen::Vector2d& pixel);

}  // namespace strata::tracking
