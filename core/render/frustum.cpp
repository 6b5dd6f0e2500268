#include "render/frustum.hpp"

#include <cmath>

namespace strata {

Frustum::Frustum(const glm::mat4& m) {
    // Clip-space tests on p' = M p: -w <= x <= w, -w <= y <= w, 0 <= z <= w. Each is a plane
    // in world space from the rows of M (GLM is column-major: row i is (m[0][i], .., m[3][i])).
    auto row = [&](int i) { return glm::vec4(m[0][i], m[1][i], m[2][i], m[3][i]); };
    const glm::vec4 x = row(0), y = row(1), z = row(2), w = row(3);
    planes_ = {w + x, w - x, w + y, w - y, z, w - z};
    for (glm::vec4& p : planes_) {
        const float length = glm::length(glm::vec3(p));
        if (length > 0.0f && std::isfinite(length)) p /= length;
        else p = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);  // degenerate: a plane that culls nothing
    }
}

bool Frustum::mayContain(const Bounds& b) const {
    return !b.empty() && classify(b.center(), b.radius()) != Side::Outside;
}

Frustum::Side Frustum::classify(const glm::vec3& c, float r) const {
    Side side = Side::Inside;
    for (const glm::vec4& p : planes_) {
        const float distance = glm::dot(glm::vec3(p), c) + p.w;
        if (distance < -r) return Side::Outside;
        if (distance < r) side = Side::Straddles;
    }
    return side;
}

}  // namespace strata
