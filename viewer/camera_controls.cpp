#include "camera_controls.hpp"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace strata {
namespace {

constexpr float kOrbitRadiansPerPixel = 0.006f;
constexpr float kLookRadiansPerPixel = 0.003f;
constexpr float kZoomPerStep = 0.88f;
constexpr float kFastFactor = 4.0f;
// Short of straight up/down, where yaw becomes undefined.
constexpr float kMaxPitch = 0.5f * glm::pi<float>() - 1e-3f;

}  // namespace

CameraControls::CameraControls(const Camera& camera, const Bounds& bounds) : base_(camera), bounds_(bounds) {
    if (bounds_.empty()) bounds_.extend(glm::vec3(0.0f));
    target_ = bounds_.center();
    speed_ = std::max(0.5f * bounds_.radius(), 1e-3f);
    setPose(camera.position, camera.orientation);
}

void CameraControls::setPose(const glm::vec3& position, const glm::quat& orientation) {
    position_ = position;
    glm::vec3 f = glm::normalize(orientation * glm::vec3(0.0f, 0.0f, -1.0f));
    // forward = (-cos p sin y, sin p, -cos p cos y) for orientation = R_y(yaw) R_x(pitch).
    pitch_ = std::clamp(std::asin(std::clamp(f.y, -1.0f, 1.0f)), -kMaxPitch, kMaxPitch);
    yaw_ = std::atan2(-f.x, -f.z);
    if (mode_ == NavigationMode::Orbit) orbitFromPosition();
}

void CameraControls::orbitFromPosition() {
    glm::vec3 toTarget = target_ - position_;
    distance_ = glm::length(toTarget);
    if (distance_ < 1e-6f) {
        // Standing on the centre: back off along the current view direction.
        distance_ = std::max(bounds_.radius() * 2.0f, 1e-3f);
        position_ = target_ - forward() * distance_;
        return;
    }
    glm::vec3 f = toTarget / distance_;
    pitch_ = std::clamp(std::asin(std::clamp(f.y, -1.0f, 1.0f)), -kMaxPitch, kMaxPitch);
    yaw_ = std::atan2(-f.x, -f.z);
}

void CameraControls::toggleMode() {
    if (mode_ == NavigationMode::Orbit) {
        mode_ = NavigationMode::Walk;
    } else {
        mode_ = NavigationMode::Orbit;
        orbitFromPosition();
        position_ = target_ - forward() * distance_;
    }
}

glm::quat CameraControls::orientation() const {
    return glm::angleAxis(yaw_, glm::vec3(0.0f, 1.0f, 0.0f)) * glm::angleAxis(pitch_, glm::vec3(1.0f, 0.0f, 0.0f));
}

glm::vec3 CameraControls::forward() const { return orientation() * glm::vec3(0.0f, 0.0f, -1.0f); }

void CameraControls::update(const NavigationInput& input) {
    if (mode_ == NavigationMode::Orbit) {
        yaw_ -= input.dragOrbit.x * kOrbitRadiansPerPixel;
        pitch_ = std::clamp(pitch_ - input.dragOrbit.y * kOrbitRadiansPerPixel, -kMaxPitch, kMaxPitch);
        if (input.scroll != 0.0f) {
            float minDistance = std::max(bounds_.radius() * 1e-3f, 1e-4f);
            float maxDistance = std::max(bounds_.radius() * 100.0f, 1.0f);
            distance_ = std::clamp(distance_ * std::pow(kZoomPerStep, input.scroll), minDistance, maxDistance);
        }
        position_ = target_ - forward() * distance_;
        return;
    }
    yaw_ -= input.dragLook.x * kLookRadiansPerPixel;
    pitch_ = std::clamp(pitch_ - input.dragLook.y * kLookRadiansPerPixel, -kMaxPitch, kMaxPitch);
    // Scroll in walk mode changes the walking speed.
    if (input.scroll != 0.0f) speed_ = std::clamp(speed_ * std::pow(1.25f, input.scroll), 1e-4f, 1e6f);
    glm::quat q = orientation();
    glm::vec3 right = q * glm::vec3(1.0f, 0.0f, 0.0f);
    glm::vec3 ahead = q * glm::vec3(0.0f, 0.0f, -1.0f);
    glm::vec3 step = input.move.x * right + input.move.z * ahead + input.move.y * glm::vec3(0.0f, 1.0f, 0.0f);
    if (glm::dot(step, step) > 0.0f) {
        float s = speed_ * (input.fast ? kFastFactor : 1.0f) * float(input.dt);
        position_ += glm::normalize(step) * s;
    }
}

Camera CameraControls::camera() const {
    Camera c = base_;
    c.position = position_;
    c.orientation = orientation();
    c.fitClipPlanes(bounds_);
    return c;
}

}  // namespace strata
