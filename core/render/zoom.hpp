#pragma once
// Zoom rendering (Mazuryk, Schmalstieg, Gervautz 1996): a display of W x H pixels is drawn at
// (ceil(W/z), ceil(H/z)) and enlarged by integer pixel replication (optionally with a blur), so
// the pixel stage does about 1/z^2 of the work.
//
// Pixel grid: reduced pixel (i, j) stands for display pixels [iz, iz + z) x [jz, jz + z),
// anchored at the bottom-left corner (GL window coordinates). When z does not divide W (or H),
// the last reduced column (row) reaches past the display's edge: its frustum is widened by that
// fraction (zoomProjection), so the centre of every display pixel lies in exactly one reduced
// pixel and replication is exact, never stretched by a non-integer factor.
#include <glm/glm.hpp>

#include <string_view>

namespace strata {

inline constexpr int kMaxZoom = 16;

// Throws std::invalid_argument for a zoom outside 1..kMaxZoom or a non-positive size.
glm::ivec2 zoomRenderSize(glm::ivec2 displaySize, int zoom);

// The projection of the reduced frame: `displayProjection` (for the display's aspect) followed
// by the map from display NDC to reduced NDC, x_r = x_d k + (k - 1) with k = W / (z ceil(W/z))
// (and likewise in y), so display pixel X lands at reduced pixel X / z. Identity at z = 1.
glm::mat4 zoomProjection(const glm::mat4& displayProjection, glm::ivec2 displaySize, int zoom);

// "1".."16"; throws std::invalid_argument naming the text otherwise.
int parseZoom(std::string_view text);

}  // namespace strata
