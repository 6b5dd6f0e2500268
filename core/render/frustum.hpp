#pragma once
// View-frustum culling: the six planes of a view-projection (GL clip space with
// glClipControl's ZERO_TO_ONE depth, as every frame draws), and whether an object's bounding
// sphere can reach the view. Conservative: a sphere is culled only when it lies wholly outside
// one plane, so nothing visible is ever culled (a sphere near a frustum corner may be kept).
// The sphere, not the box, because a stand-in's slice quads reach past the object's box within
// its bounding sphere (lod/layered_impostor.hpp).
#include "scene/scene.hpp"

#include <glm/glm.hpp>

#include <array>

namespace strata {

class Frustum {
public:
    explicit Frustum(const glm::mat4& viewProjection);
    // Whether the bounding sphere of `b` (centre, half diagonal) reaches inside every plane.
    // Empty bounds (no geometry) never do.
    bool mayContain(const Bounds& b) const;

    enum class Side { Outside, Straddles, Inside };
    // A sphere wholly outside one plane, wholly inside all six, or neither (then what it holds
    // must be tested one by one). Conservative like mayContain.
    Side classify(const glm::vec3& centre, float radius) const;

private:
    std::array<glm::vec4, 6> planes_;  // (normal, offset), normalised; inside where n.p + d >= 0
};

}  // namespace strata
