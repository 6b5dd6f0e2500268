#pragma once
// Showing a frame in the window: linear-RGB textures drawn into the default framebuffer,
// sRGB-encoded by shaders/frame/present.frag.glsl, each into its own region (the whole window, or
// one eye of side-by-side stereo). One presenter serves every window mode.
#include "gl/objects.hpp"

#include <glm/glm.hpp>

#include <span>

namespace strata {

// A linear-RGB texture shown at `origin` (window pixels, GL's bottom-left origin), `size` wide.
struct PresentRegion {
    GLuint texture = 0;
    glm::ivec2 origin{0};
    glm::ivec2 size{0};
};

class Presenter {
public:
    // Builds the present program; throws std::runtime_error (file:line) when it does not compile.
    Presenter();

    // F5: rebuilds the program from the file on disk. On failure it throws and keeps the old one.
    void reload();

    // Clears the window to black and draws each region; leaves the viewport on the whole window
    // and no program bound, for the ImGui panel drawn next.
    void present(glm::ivec2 windowSize, std::span<const PresentRegion> regions) const;

private:
    gl::Program program_;
    GLint originLocation_ = -1;
    gl::VertexArray emptyVertexArray_;  // the full-screen triangle comes from gl_VertexID
};

}  // namespace strata
