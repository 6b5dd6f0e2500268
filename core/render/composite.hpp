#pragma once
// A transparent surface fragment as the exact reference (CPU ray cast, analytic tests) sees it,
// and the total order by (depth, object id, primitive id). The compositing order built on it,
// with the tie rule for coincident surfaces, is in render/depth_order.hpp.
#include <glm/glm.hpp>


namespace strata {

struct SurfaceFragment {
    float depth = 0.0f;   // distance-like key: smaller is nearer (CPU: eye depth)
    int object = 0;
    int primitive = 0;
    glm::vec3 color{0.0f};  // shaded colour, not premultiplied
    float alpha = 0.0f;
    bool frontFacing = true;
    // A coloured filter (a transmissive material): what passes behind it per channel, where
    // alpha * color is still its premultiplied colour and alpha the scalar form the techniques
    // without RGB transmittance composite (common/shading_model.h's scalarOpacityForm).
    bool coloredFilter = false;
    glm::vec3 transmittance{1.0f};

    // What passes behind the fragment, per channel.
    glm::vec3 passes() const { return coloredFilter ? transmittance : glm::vec3(1.0f - alpha); }
};

inline bool nearerFirst(const SurfaceFragment& a, const SurfaceFragment& b) {
    if (a.depth != b.depth) return a.depth < b.depth;
    if (a.object != b.object) return a.object < b.object;
    return a.primitive < b.primitive;
}

}  // namespace strata
