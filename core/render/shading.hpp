#pragma once
// The one shading model every renderer uses, on the CPU (reference) and in GLSL
// (shaders/common/shading.glsl mirrors it line for line). Two-sided Lambert with an ambient
// floor, so back faces of transparent objects are lit like front faces.
#include <glm/glm.hpp>

#include <cmath>

namespace strata {

constexpr float kAmbient = 0.3f;

inline glm::vec3 shadeSurface(const glm::vec3& baseColor, const glm::vec3& normal,
                              const glm::vec3& lightDirection) {
    float len = glm::length(normal);
    float ndl = len > 0.0f ? std::abs(glm::dot(normal / len, lightDirection)) : 1.0f;
    return baseColor * (kAmbient + (1.0f - kAmbient) * ndl);
}

}  // namespace strata
