#include "render/depth_order.hpp"

#include <algorithm>

namespace strata {

int orderFragments(std::vector<SurfaceFragment>& fragments, double tolerance) {
    std::sort(fragments.begin(), fragments.end(), nearerFirst);
    auto byScene = [](const SurfaceFragment& a, const SurfaceFragment& b) {
        if (a.object != b.object) return a.object < b.object;
        if (a.primitive != b.primitive) return a.primitive < b.primitive;
        return a.depth < b.depth;
    };
    int ties = 0;
    std::size_t start = 0;
    for (std::size_t i = 1; i <= fragments.size(); ++i) {
        if (i < fragments.size() && sameDepthLayer(fragments[i - 1].depth, fragments[i].depth, tolerance)) {
            ++ties;
            continue;
        }
        if (i - start > 1)
            std::sort(fragments.begin() + std::ptrdiff_t(start), fragments.begin() + std::ptrdiff_t(i), byScene);
        start = i;
    }
    return ties;
}

glm::vec3 compositeOrdered(const std::vector<SurfaceFragment>& ordered, const glm::vec3& background) {
    glm::vec3 color(0.0f);
    glm::vec3 transmittance(1.0f);
    for (const auto& f : ordered) {
        color += transmittance * f.alpha * f.color;
        transmittance *= f.passes();
    }
    return color + transmittance * background;
}

glm::vec3 compositeInDepthOrder(std::vector<SurfaceFragment>& fragments, const glm::vec3& background,
                                double tolerance) {
    orderFragments(fragments, tolerance);
    return compositeOrdered(fragments, background);
}

}  // namespace strata
