#pragma once
// Image deflection on the GPU: a full-screen pass that moves a finished colour image (e.g.
// FrameTargets::outputColor()) to fit a newer head pose, the second step of two-step prediction
// (Mazuryk & Gervautz 1995). The math that produces the parameters lives in tracking/ (CPU, no
// GL); this side takes plain glm values so strata_core never depends on strata_tracking.
//
// Pixel convention here: GL window coordinates, origin at the bottom-left corner of the
// bottom-left pixel, x right, y up, pixel (i, j) covering [i, i+1) x [j, j+1) with its centre at
// (i + 0.5, j + 0.5) (gl_FragCoord). Both modes are evaluated as an inverse map: for each output
// pixel centre p the pass samples the source at s = M p (homogeneous), so every output pixel is
// written exactly once and no holes appear.
//  - shift: M = translate(-shift): the content moves by +shift pixels (x right, y up).
//  - homography: M is given directly, output pixel -> source pixel.
// Producers with other conventions convert first; tracking/deflection.hpp uses a forward map
// (rendered -> latest) in y-down, top-left-origin pixels, which homographyFromYDownForward and
// shiftFromYDown turn into this convention.
//
// Sampling: `nearest` reads the texel containing s; `bilinear` interpolates the four texels
// around s by hand (texelFetch with float weights, clamped to the edge texels), so the result
// does not depend on the driver's filter precision or on the source texture's filter state.
// An output pixel whose s lies outside [0, w] x [0, h] gets the border colour and, when asked,
// is counted (one atomic counter; reading the count waits for the GPU).
//
// Zoom rendering (render/zoom.hpp) folds into the same pass: with `zoom` z > 1 the source is the
// frame drawn at zoomRenderSize(size, z) and the map still speaks in display pixels; the display
// position s is read from source texel s / z. The identity map with `nearest` is then pixel
// replication (the paper's enlargement, exact), `bilinear` the fast blur; a deflected frame is
// enlarged and moved at once, and a small source is what is read.
#include "gl/objects.hpp"
#include "image/image.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <string_view>

namespace strata {

enum class DeflectMode { Shift, Homography };
enum class DeflectFilter { Nearest, Bilinear };

std::string_view deflectFilterName(DeflectFilter f);
// Throws std::invalid_argument for anything but nearest, bilinear.
DeflectFilter parseDeflectFilter(std::string_view name);

struct DeflectionParams {
    DeflectMode mode = DeflectMode::Shift;
    glm::vec2 shift{0.0f};           // GL pixels; content moves by +shift (x right, y up)
    glm::mat3 homography{1.0f};      // output GL pixel -> source GL pixel (the inverse map)
    DeflectFilter filter = DeflectFilter::Bilinear;
    glm::vec4 border{0.0f, 0.0f, 0.0f, 1.0f};
    bool countOutside = false;       // count output pixels that sample outside the source
    int zoom = 1;                    // display pixels per source texel, a side (render/zoom.hpp)
};

// The inverse map the pass evaluates for `params` (either mode), output -> source.
glm::mat3 deflectionInverseMap(const DeflectionParams& params);

// Converts a forward homography (source -> output pixels) given in y-down pixel coordinates
// with the origin at the top-left corner (tracking::deflectionHomography) into this pass's
// inverse map in GL coordinates. With F = [1 0 0; 0 -1 h; 0 0 1] (its own inverse) the GL
// forward map is F H F and the inverse map is F H^-1 F. Inverted in double precision.
glm::mat3 homographyFromYDownForward(const glm::dmat3& forwardYDown, int height);
// A y-down shift (tracking::deflectionShift) in GL's y-up pixels: (x, -y).
inline glm::vec2 shiftFromYDown(glm::dvec2 shiftYDown) {
    return glm::vec2(float(shiftYDown.x), float(-shiftYDown.y));
}

class DeflectionWarp {
public:
    // Warps `sourceTexture` (a 2D RGBA texture of zoomRenderSize(size, params.zoom)) into this
    // warp's own RGBA32F target of `size`, reallocated when the size changes. Throws
    // std::invalid_argument when the source's size is not that. Leaves framebuffer 0 bound, depth
    // test, blending and scissor off.
    void apply(GLuint sourceTexture, glm::ivec2 size, const DeflectionParams& params);

    GLuint outputColor() const { return color_.id(); }
    GLuint outputFramebuffer() const { return fbo_.id(); }
    glm::ivec2 size() const { return size_; }
    // Output pixels that sampled outside the source in the last apply() with countOutside;
    // 0 otherwise. Waits for the pass to finish.
    std::uint64_t outsidePixels() const;
    // The last output (linear RGBA, bottom row first).
    Image readOutput() const;

private:
    void resize(glm::ivec2 size);

    glm::ivec2 size_{0, 0};
    gl::Program program_, replicateProgram_;
    gl::Texture color_;
    gl::Framebuffer fbo_;
    gl::VertexArray emptyVertexArray_;
    gl::Buffer counter_;
    bool counted_ = false;
};

}  // namespace strata
