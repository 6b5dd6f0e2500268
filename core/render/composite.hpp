#pragma once
// The compositing model shared by the exact reference (GPU abuffer, CPU ray cast) and the
// analytic tests: fragments sorted front to back by (depth, object id, primitive id),
// composited with "under" (front to back), then over the opaque colour.
#include <glm/glm.hpp>

#include <algorithm>
#include <vector>

namespace strata {

struct SurfaceFragment {
    float depth = 0.0f;   // distance-like key: smaller is nearer (CPU: eye depth)
    int object = 0;
    int primitive = 0;
    glm::vec3 color{0.0f};  // shaded colour, not premultiplied
    float alpha = 0.0f;
    bool frontFacing = true;
};

inline bool nearerFirst(const SurfaceFragment& a, const SurfaceFragment& b) {
    if (a.depth != b.depth) return a.depth < b.depth;
    if (a.object != b.object) return a.object < b.object;
    return a.primitive < b.primitive;
}

// Front-to-back: C += T * a * c; T *= (1 - a); result = C + T * background.
inline glm::vec3 compositeFrontToBack(std::vector<SurfaceFragment>& fragments, const glm::vec3& background) {
    std::sort(fragments.begin(), fragments.end(), nearerFirst);
    glm::vec3 color(0.0f);
    float transmittance = 1.0f;
    for (const auto& f : fragments) {
        color += transmittance * f.alpha * f.color;
        transmittance *= 1.0f - f.alpha;
    }
    return color + transmittance * background;
}

}  // namespace strata
