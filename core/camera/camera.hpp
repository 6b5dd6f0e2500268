#pragma once
// Perspective camera with reversed-Z depth.
//
// Depth convention: reversed-Z in a 32-bit float depth buffer, glClipControl(LOWER_LEFT,
// ZERO_TO_ONE), cleared to 0, tested with GL_GREATER; window depth is 1 at the near plane
// and 0 at the far plane. Float precision is densest near 0, which reversed-Z spends on the
// far range where the 1/z mapping is sparse: the error is nearly uniform in log depth, so
// near/far ratios of 1e6 still separate surfaces, and coplanar surfaces are the only ties.
// "Nearer" therefore means "larger window depth" everywhere in this code and the shaders.
#include "scene/scene.hpp"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace strata {

struct Camera {
    glm::vec3 position{0.0f, 0.0f, 5.0f};
    glm::quat orientation{1.0f, 0.0f, 0.0f, 0.0f};  // local -Z is the viewing direction, +Y up
    float fovYDegrees = 50.0f;
    float nearPlane = 0.05f;
    float farPlane = 500.0f;

    glm::vec3 forward() const { return orientation * glm::vec3(0.0f, 0.0f, -1.0f); }
    glm::vec3 up() const { return orientation * glm::vec3(0.0f, 1.0f, 0.0f); }
    glm::vec3 right() const { return orientation * glm::vec3(1.0f, 0.0f, 0.0f); }

    glm::mat4 view() const;
    // Reversed-Z projection for a [0,1] clip range: window depth 1 at near, 0 at far.
    glm::mat4 projection(float aspect) const;

    // Places the camera at `eye` looking at `target` with `up` as the up hint.
    void lookAt(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& upHint = {0, 1, 0});
    // Sets near/far to enclose `bounds` seen from the current position (near/far >= 1e-6).
    void fitClipPlanes(const Bounds& bounds);
};

// A camera that frames `bounds` from a three-quarter view, with clip planes fitted.
Camera frameBounds(const Bounds& bounds, float fovYDegrees = 50.0f);

// The scene's own camera if it has one, else one fitted to its bounds.
Camera defaultCamera(const Scene& scene, const std::vector<Object>& objects);

}  // namespace strata
