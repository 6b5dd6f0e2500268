#pragma once
// Walkthrough controls for the viewer: orbit around the scene bounds' centre (drag to turn,
// scroll to zoom) or walk (WASD + QE, mouse-look, shift faster). Plain math on a Camera; the
// window code feeds it input, so it holds no GLFW or GL state.
#include "camera/camera.hpp"
#include "scene/scene.hpp"

#include <glm/glm.hpp>

namespace strata {

enum class NavigationMode { Orbit, Walk };

// What the window saw since the last frame.
struct NavigationInput {
    glm::vec2 dragOrbit{0.0f};   // pixels dragged with the orbit button (left)
    glm::vec2 dragLook{0.0f};    // pixels dragged with the look button (right)
    float scroll = 0.0f;         // wheel steps, positive = towards the target
    glm::vec3 move{0.0f};        // walk: x right, y up, z forward; each in [-1, 1]
    bool fast = false;           // shift held
    double dt = 0.0;             // seconds since the last frame
};

class CameraControls {
public:
    // Starts from `camera` (its pose, field of view) orbiting `bounds`' centre.
    CameraControls(const Camera& camera, const Bounds& bounds);

    NavigationMode mode() const { return mode_; }
    const char* modeName() const { return mode_ == NavigationMode::Orbit ? "orbit" : "walk"; }
    // Orbit -> walk keeps the pose; walk -> orbit turns to face the bounds' centre from where
    // the camera stands.
    void toggleMode();

    void update(const NavigationInput& input);
    // Takes over a pose set from outside (camera path playback) so control resumes from it.
    void setPose(const glm::vec3& position, const glm::quat& orientation);

    // The camera with clip planes fitted to the bounds.
    Camera camera() const;
    float orbitDistance() const { return distance_; }
    float walkSpeed() const { return speed_; }

private:
    void orbitFromPosition();
    glm::quat orientation() const;
    glm::vec3 forward() const;

    Camera base_;
    Bounds bounds_;
    glm::vec3 target_{0.0f};
    NavigationMode mode_ = NavigationMode::Orbit;
    glm::vec3 position_{0.0f};
    float yaw_ = 0.0f;     // radians about +Y; 0 looks down -Z
    float pitch_ = 0.0f;   // radians, positive looks up
    float distance_ = 1.0f;
    float speed_ = 1.0f;   // walk speed, scene units per second
};

}  // namespace strata
