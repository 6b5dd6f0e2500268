#pragma once
// The error view's GPU pass: per-pixel |image - reference| of two linear RGBA32F textures of one
// frame, in false colour (shaders/debug/error_map.comp.glsl), and the figures the panel and the
// smoke tests show: RMSE and PSNR over RGB (the same definitions as compareImages in
// image/image.hpp, so the view agrees with the bench) and the worst pixel with its value.
// The reduction runs on the GPU per 8x8 group; the host adds the groups in double.
#include "gl/objects.hpp"
#include "image/image.hpp"

#include <glm/glm.hpp>

#include <cstddef>

namespace strata {

struct ErrorMapStats {
    double rmse = 0.0;           // over every RGB channel of every pixel, linear
    double psnr = 100.0;         // dB, peak 1, 100 when nothing differs (as compareImages)
    double maxAbsError = 0.0;    // largest per-channel difference
    glm::ivec2 worstPixel{-1};   // where it is (row 0 at the bottom); (-1, -1) for an empty image
    std::size_t pixels = 0;
};

class ErrorMap {
public:
    // Builds the program; throws std::runtime_error (file:line) when it does not compile.
    ErrorMap();

    // Compares `image` with `reference` (both RGBA32F textures of `size`); writes the false
    // colour to falseColor() unless `falseColour` is false (stats only) and returns the figures.
    // `scale`: the error shown as full red (> 0).
    ErrorMapStats compare(GLuint image, GLuint reference, glm::ivec2 size, float scale = 0.05f,
                          bool falseColour = true);

    // The last false-colour image (RGBA32F, linear, the size of the last compare); 0 before any.
    GLuint falseColor() const { return falseColor_.id(); }
    glm::ivec2 size() const { return size_; }

private:
    gl::Program program_;
    GLint scaleLocation_ = -1;
    gl::Texture falseColor_;
    gl::Texture scratch_;  // the target when the false colour is not wanted
    glm::ivec2 size_{0}, scratchSize_{0};
    gl::Buffer partials_;
    std::size_t partialCapacity_ = 0;
};

// The same false colour on the CPU, for images already read back (the bench report's error maps):
// per pixel what ErrorMap::compare writes for `image` against `reference` at `scale`. Throws
// std::invalid_argument when the sizes differ or scale is not > 0.
Image errorMapImage(const Image& image, const Image& reference, float scale = 0.05f);

// The false colour of an error of `t` x scale (0 < t; clamped at 1): the legend's ramp.
glm::vec3 errorMapRamp(float t);

}  // namespace strata
