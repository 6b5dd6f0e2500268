#include "scene/mesh_builders.hpp"

#include <glm/gtc/constants.hpp>

namespace strata {

Mesh makeQuad(float width, float height) {
    Mesh m;
    m.name = "quad";
    float x = width * 0.5f, y = height * 0.5f;
    m.positions = {{-x, -y, 0}, {x, -y, 0}, {x, y, 0}, {-x, y, 0}};
    m.normals.assign(4, {0, 0, 1});
    m.indices = {0, 1, 2, 0, 2, 3};
    return m;
}

Mesh makeBox(const glm::vec3& lo, const glm::vec3& hi) {
    Mesh m;
    m.name = "box";
    // Each face: an outward normal and its four corners counter-clockwise seen from outside.
    struct Face { glm::vec3 n; glm::vec3 c[4]; };
    const Face faces[6] = {
        {{1, 0, 0}, {{hi.x, lo.y, hi.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {hi.x, hi.y, hi.z}}},
        {{-1, 0, 0}, {{lo.x, lo.y, lo.z}, {lo.x, lo.y, hi.z}, {lo.x, hi.y, hi.z}, {lo.x, hi.y, lo.z}}},
        {{0, 1, 0}, {{lo.x, hi.y, hi.z}, {hi.x, hi.y, hi.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z}}},
        {{0, -1, 0}, {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, lo.y, hi.z}, {lo.x, lo.y, hi.z}}},
        {{0, 0, 1}, {{lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}}},
        {{0, 0, -1}, {{hi.x, lo.y, lo.z}, {lo.x, lo.y, lo.z}, {lo.x, hi.y, lo.z}, {hi.x, hi.y, lo.z}}},
    };
    for (const Face& f : faces) {
        auto base = std::uint32_t(m.positions.size());
        for (const auto& c : f.c) { m.positions.push_back(c); m.normals.push_back(f.n); }
        m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
    return m;
}

Mesh makeSphere(float radius, int segments, int rings) {
    Mesh m;
    m.name = "sphere";
    for (int r = 0; r <= rings; ++r) {
        float theta = glm::pi<float>() * float(r) / float(rings);
        for (int s = 0; s <= segments; ++s) {
            float phi = glm::two_pi<float>() * float(s) / float(segments);
            glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi));
            m.positions.push_back(n * radius);
            m.normals.push_back(n);
        }
    }
    auto at = [&](int r, int s) { return std::uint32_t(r * (segments + 1) + s); };
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            // Skip the degenerate triangles at the poles.
            if (r != 0) m.indices.insert(m.indices.end(), {at(r, s), at(r + 1, s), at(r, s + 1)});
            if (r != rings - 1) m.indices.insert(m.indices.end(), {at(r, s + 1), at(r + 1, s), at(r + 1, s + 1)});
        }
    return m;
}

}  // namespace strata
