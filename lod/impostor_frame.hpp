#pragma once
// The back-perspective frame of one baked view (Schaufler section 3.1, Fig. 1 bottom): for a
// bounding sphere (centre c, radius r) in object space and a view direction v (unit, from the
// centre towards the viewer's side), the apex sits at c - v * D on the side AWAY from the
// viewer, the axis points along +v (through the centre towards the viewer), and the square
// frustum just encloses the sphere. Rays diverge from the apex, so one image samples the
// surface the viewer sees plus some of what lies round its silhouette.
//
// Slices are planes perpendicular to the axis at uniform steps of the distance from the apex
// over the slab [D - r, D + r]; t in [0, 1] is that distance normalised over the slab (t = 0 at
// the plane nearest the apex). u, v in [0, 1] cross the frustum (same texel, same ray from the
// apex); u along `right`, v along `up`, texel (i, j) = floor(u * res), floor(v * res).
#include <glm/glm.hpp>

#include <array>

namespace strata::lod {

// D = kDefaultApexFactor * r. At 3r the frustum's half-angle is asin(1/3) = 19.5 deg: the image
// reaches that far round the silhouette (surfaces the nearest-view warp exposes), the slab's
// near plane (2r) and far plane (4r) differ in texel size by only 2x, and the field is narrow
// enough that the centre keeps most of the resolution. Nearer apexes (D -> r) widen the field
// towards 180 deg and waste texels at the rim; far ones tend to an orthographic image.
inline constexpr float kDefaultApexFactor = 3.0f;

// A rectangle in [0, 1]^2 of the (u, v) square.
struct UvRect {
    glm::vec2 min{0.0f};
    glm::vec2 max{1.0f};
};

struct ImpostorFrame {
    glm::vec3 centre{0.0f};
    float radius = 1.0f;
    glm::vec3 axis{0.0f, 0.0f, 1.0f};  // = the view direction v
    glm::vec3 right{1.0f, 0.0f, 0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    glm::vec3 apex{0.0f};
    float apexDistance = 3.0f;  // D
    float tanHalf = 0.0f;       // tan of the frustum's half-angle: r / sqrt(D^2 - r^2)

    float slabNear() const { return apexDistance - radius; }
    float slabFar() const { return apexDistance + radius; }
    // Distance from the apex of slice s's plane: the middle of its interval [s/L, (s+1)/L) of t.
    float sliceDistance(int slice, int slices) const;
    // The quad of slice s (corners counter-clockwise seen from the apex) restricted to
    // `rect`: corners at (min.x,min.y), (max.x,min.y), (max.x,max.y), (min.x,max.y); the plane moved
    // `offsetSlices` slice widths along the axis (negative: towards the apex).
    std::array<glm::vec3, 4> sliceQuad(int slice, int slices, const UvRect& rect = {}, float offsetSlices = 0.0f) const;
    // Object-space point -> (u, v, t). Inside the sphere all three lie in [0, 1].
    glm::vec3 toUvt(const glm::vec3& p) const;
    // (u, v, t) -> object-space point (the inverse of toUvt).
    glm::vec3 fromUvt(const glm::vec3& uvt) const;
    // The bake's camera: view (apex looking along +axis, camera x = right, y = up) and a
    // projection for a [0, 1] clip range (glClipControl ZERO_TO_ONE) with depth 0 at the slab's
    // near plane and 1 at its far plane, both pushed out by a thousandth so the sphere is inside.
    glm::mat4 view() const;
    glm::mat4 projection() const;
};

// The frame for view direction `v` (normalised here). apexFactor > 1 (D = apexFactor * r).
ImpostorFrame makeImpostorFrame(const glm::vec3& centre, float radius, const glm::vec3& v,
                                float apexFactor = kDefaultApexFactor);

}  // namespace strata::lod
