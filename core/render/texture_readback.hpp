#pragma once
// Reading a linear RGBA colour texture back into an Image, for the frame's output, the deflected
// frame and the coplanarity heatmap alike (tests, screenshots, the bench's error figures).
#include "gl/objects.hpp"
#include "image/image.hpp"

#include <glm/glm.hpp>

namespace strata {

// `texture` holds `size` texels of a colour format GL converts to RGBA float; row 0 at the bottom.
Image readRgbaTexture(GLuint texture, glm::ivec2 size);

}  // namespace strata
