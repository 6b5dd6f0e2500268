#include "camera/camera.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace strata {

glm::mat4 Camera::view() const {
    glm::mat4 rotation = glm::mat4_cast(glm::conjugate(orientation));
    return rotation * glm::translate(glm::mat4(1.0f), -position);
}

glm::mat4 Camera::projection(float aspect) const {
    float f = 1.0f / std::tan(glm::radians(fovYDegrees) * 0.5f);
    float n = nearPlane, fa = farPlane;
    glm::mat4 p(0.0f);
    p[0][0] = f / aspect;
    p[1][1] = f;
    // z_clip = n (f - d) / (f - n) for eye distance d, w_clip = d: window depth 1 at d = n, 0 at d = f.
    p[2][2] = n / (fa - n);
    p[3][2] = fa * n / (fa - n);
    p[2][3] = -1.0f;
    return p;
}

void Camera::lookAt(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& upHint) {
    position = eye;
    glm::vec3 dir = target - eye;
    if (glm::length(dir) < 1e-12f) return;
    glm::vec3 hint = upHint;
    if (std::abs(glm::dot(glm::normalize(dir), glm::normalize(hint))) > 0.999f) hint = {0, 0, 1};
    // glm::lookAt builds the view matrix; the camera's orientation is its inverse rotation.
    glm::mat4 v = glm::lookAt(eye, target, hint);
    orientation = glm::normalize(glm::conjugate(glm::quat_cast(glm::mat3(v))));
}

void Camera::fitClipPlanes(const Bounds& bounds) {
    if (bounds.empty()) return;
    float radius = std::max(bounds.radius(), 1e-4f);
    float distance = glm::length(bounds.center() - position);
    farPlane = distance + radius * 1.05f;
    nearPlane = std::max(std::max(distance - radius * 1.05f, farPlane * 1e-4f), 1e-6f);
}

Camera frameBounds(const Bounds& bounds, float fovYDegrees) {
    Camera camera;
    camera.fovYDegrees = fovYDegrees;
    if (bounds.empty()) return camera;
    glm::vec3 center = bounds.center();
    float radius = std::max(bounds.radius(), 1e-4f);
    float distance = radius / std::sin(glm::radians(fovYDegrees) * 0.5f) * 1.05f;
    glm::vec3 direction = glm::normalize(glm::vec3(0.45f, 0.35f, 1.0f));
    camera.lookAt(center + direction * distance, center);
    camera.fitClipPlanes(bounds);
    return camera;
}

Camera defaultCamera(const Scene& scene, const std::vector<Object>& objects) {
    Bounds bounds = worldBounds(scene, objects);
    if (!scene.camera) return frameBounds(bounds);
    Camera camera;
    camera.position = scene.camera->position;
    camera.orientation = scene.camera->orientation;
    camera.fovYDegrees = scene.camera->fovYDegrees;
    camera.fitClipPlanes(bounds);
    return camera;
}

}  // namespace strata
