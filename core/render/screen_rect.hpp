#pragma once
// Where world-space bounds land on screen: the normalized-device rectangle and depth range of a
// box's eight corners under a view-projection (GL clip space, glClipControl ZERO_TO_ONE,
// reversed-Z), and the pixel rectangle that holds it. Conservative: the box is inflated beyond
// the round-off between this projection and the rasterized geometry, and a box reaching behind
// the eye covers the whole screen and depth range (it projects without bound).
#include "scene/scene.hpp"

#include <glm/glm.hpp>

namespace strata {

struct ScreenProjection {
    glm::vec2 ndcMin{-1.0f}, ndcMax{1.0f};
    float farDepth = 0.0f, nearDepth = 1.0f;  // window depth, reversed-Z, within [0, 1]
    bool behindEye = false;                    // the whole screen and depth range
};

ScreenProjection projectBox(const glm::mat4& viewProjection, const Bounds& box);

// A rectangle of whole pixels: origin (lower left) and size; `size` 0 holds nothing.
struct PixelRect {
    glm::ivec2 origin{0, 0}, size{0, 0};
    bool empty() const { return size.x <= 0 || size.y <= 0; }
    PixelRect unite(const PixelRect& other) const;
    PixelRect intersect(const PixelRect& other) const;  // empty where they do not overlap
};

// The pixels of a frame of `frameSize` that a projection covers, with one more on each side
// for round-off, clipped to the frame. With `cellSize` > 1, in cells of that many pixels a side
// (the frame then has ceil(frameSize / cellSize) of them, as a reduced target): the cells that
// hold those pixels, with one more cell on each side.
PixelRect pixelRect(const ScreenProjection& p, glm::ivec2 frameSize, int cellSize = 1);

// Every pixel an object with these world bounds can draw to: the pixel rectangle of the cube
// around its bounding sphere (centre, half diagonal). The sphere, as for culling
// (render/frustum.hpp): a stand-in's slice quads reach past its box within that sphere.
PixelRect pixelsReached(const glm::mat4& viewProjection, const Bounds& bounds, glm::ivec2 frameSize);

}  // namespace strata
