#include "lod/impostor_frame.hpp"

#include <cmath>

namespace strata::lod {

ImpostorFrame makeImpostorFrame(const glm::vec3& centre, float radius, const glm::vec3& v, float apexFactor) {
    ImpostorFrame f;
    f.centre = centre;
    f.radius = radius;
    f.axis = glm::normalize(v);
    // Any up hint not parallel to the axis; right and up complete a right-handed basis with
    // -axis as the camera's z (camera looks along +axis).
    const glm::vec3 hint = std::abs(f.axis.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    f.right = glm::normalize(glm::cross(f.axis, hint));
    f.up = glm::cross(f.right, f.axis);
    f.apexDistance = apexFactor * radius;
    f.apex = centre - f.axis * f.apexDistance;
    f.tanHalf = 1.0f / std::sqrt(apexFactor * apexFactor - 1.0f);  // r / sqrt(D^2 - r^2)
    return f;
}

float ImpostorFrame::sliceDistance(int slice, int slices) const {
    return slabNear() + 2.0f * radius * (float(slice) + 0.5f) / float(slices);
}

std::array<glm::vec3, 4> ImpostorFrame::sliceQuad(int slice, int slices, const UvRect& rect, float offsetSlices) const {
    const float t = (float(slice) + 0.5f + offsetSlices) / float(slices);
    return {fromUvt({rect.min.x, rect.min.y, t}), fromUvt({rect.max.x, rect.min.y, t}),
            fromUvt({rect.max.x, rect.max.y, t}), fromUvt({rect.min.x, rect.max.y, t})};
}

glm::vec3 ImpostorFrame::toUvt(const glm::vec3& p) const {
    const glm::vec3 q = p - apex;
    const float d = glm::dot(q, axis);
    const float half = d * tanHalf;
    return {0.5f + 0.5f * glm::dot(q, right) / half, 0.5f + 0.5f * glm::dot(q, up) / half,
            (d - slabNear()) / (2.0f * radius)};
}

glm::vec3 ImpostorFrame::fromUvt(const glm::vec3& uvt) const {
    const float d = slabNear() + uvt.z * 2.0f * radius;
    const float half = d * tanHalf;
    return apex + axis * d + right * ((2.0f * uvt.x - 1.0f) * half) + up * ((2.0f * uvt.y - 1.0f) * half);
}

glm::mat4 ImpostorFrame::view() const {
    // Rows: right, up, -axis; origin at the apex.
    glm::mat4 m(1.0f);
    for (int c = 0; c < 3; ++c) {
        m[c][0] = right[c];
        m[c][1] = up[c];
        m[c][2] = -axis[c];
    }
    m[3][0] = -glm::dot(right, apex);
    m[3][1] = -glm::dot(up, apex);
    m[3][2] = glm::dot(axis, apex);
    return m;
}

glm::mat4 ImpostorFrame::projection() const {
    const float n = slabNear() * 0.999f, f = slabFar() * 1.001f;
    glm::mat4 p(0.0f);
    p[0][0] = 1.0f / tanHalf;
    p[1][1] = 1.0f / tanHalf;
    p[2][2] = f / (n - f);       // z_ndc = 0 at z_eye = -n, 1 at -f
    p[3][2] = n * f / (n - f);
    p[2][3] = -1.0f;
    return p;
}

}  // namespace strata::lod
