#include "render/screen_rect.hpp"

#include <algorithm>
#include <cmath>

namespace strata {

ScreenProjection projectBox(const glm::mat4& viewProjection, const Bounds& box) {
    // Inflated so that round-off between this projection and the rasterized geometry (a flat
    // quad has a flat box) never puts the geometry outside the box's depth range or rectangle.
    const glm::vec3 extent = box.max - box.min;
    const float pad = 1e-4f * glm::length(extent) + 1e-6f * (1.0f + glm::length(box.center()));
    const glm::vec3 lo = box.min - pad, hi = box.max + pad;
    glm::vec2 pmin(1e30f), pmax(-1e30f);
    float dmin = 1e30f, dmax = -1e30f;
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 corner((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z);
        const glm::vec4 clip = viewProjection * glm::vec4(corner, 1.0f);
        if (!(clip.w > 1e-6f)) {  // behind the eye: unbounded
            ScreenProjection all;
            all.behindEye = true;
            return all;
        }
        const glm::vec3 ndc = glm::vec3(clip) / clip.w;
        pmin = glm::min(pmin, glm::vec2(ndc));
        pmax = glm::max(pmax, glm::vec2(ndc));
        dmin = std::min(dmin, ndc.z);
        dmax = std::max(dmax, ndc.z);
    }
    ScreenProjection p;
    p.ndcMin = pmin;
    p.ndcMax = pmax;
    // Geometry is clipped to the near and far planes: its depths lie in [0, 1] (reversed-Z: 1 near).
    p.farDepth = std::clamp(dmin, 0.0f, 1.0f);
    p.nearDepth = std::clamp(dmax, 0.0f, 1.0f);
    return p;
}

PixelRect PixelRect::unite(const PixelRect& other) const {
    if (other.empty()) return *this;
    if (empty()) return other;
    const glm::ivec2 lo = glm::min(origin, other.origin);
    const glm::ivec2 hi = glm::max(origin + size, other.origin + other.size);
    return PixelRect{lo, hi - lo};
}

PixelRect PixelRect::intersect(const PixelRect& other) const {
    const glm::ivec2 lo = glm::max(origin, other.origin);
    const glm::ivec2 hi = glm::min(origin + size, other.origin + other.size);
    if (hi.x <= lo.x || hi.y <= lo.y) return PixelRect{};
    return PixelRect{lo, hi - lo};
}

PixelRect pixelRect(const ScreenProjection& p, glm::ivec2 frameSize, int cellSize) {
    const glm::vec2 cellsPerNdc = glm::vec2(frameSize) / float(cellSize);
    const glm::vec2 cells((frameSize + cellSize - 1) / cellSize);
    // The default projection (behind the eye) is [-1, 1]: the whole frame, margin clipped.
    glm::vec2 lo = glm::floor((p.ndcMin * 0.5f + 0.5f) * cellsPerNdc) - 1.0f;
    glm::vec2 hi = glm::ceil((p.ndcMax * 0.5f + 0.5f) * cellsPerNdc) + 1.0f;
    lo = glm::clamp(lo, glm::vec2(0.0f), cells);
    hi = glm::clamp(hi, glm::vec2(0.0f), cells);
    if (!(hi.x > lo.x && hi.y > lo.y)) return PixelRect{};
    return PixelRect{glm::ivec2(lo), glm::ivec2(hi - lo)};
}

PixelRect pixelsReached(const glm::mat4& viewProjection, const Bounds& bounds, glm::ivec2 frameSize) {
    if (bounds.empty()) return PixelRect{};
    const glm::vec3 c = bounds.center();
    const glm::vec3 r(bounds.radius());
    return pixelRect(projectBox(viewProjection, Bounds{c - r, c + r}), frameSize);
}

}  // namespace strata
