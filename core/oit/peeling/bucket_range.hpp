#pragma once
// Bucket peeling's depth range (Liu et al. 2009), shared by `bun` and `bun-ll`: each pixel's
// nearest (r) and minus its farthest (g) window depth in an RG32F target, MAX-blended from the
// transparent objects' bounding boxes (the default) or from the geometry itself (one more
// geometry pass, tighter buckets). shaders/oit/peeling/bun_bucket.glsl reads it.
#include "oit/technique.hpp"
#include "render/scene_program.hpp"

namespace strata::peeling {

class BucketRange {
public:
    // One pass into the range target (reallocated with the frame's size); counts it in
    // stats.passes and, from the geometry, its draws in stats.objectDraws.
    void render(const FrameContext& frame, bool fromGeometry, TechniqueStats& stats);
    GLuint texture() const { return range_.id(); }
    static constexpr std::uint64_t kBytesPerPixel = 8;

private:
    void ensure(glm::ivec2 size);

    SceneProgram geometryProgram_;
    gl::Program boxProgram_;
    gl::Buffer boxVertices_, boxIndices_;
    gl::VertexArray boxVao_;
    glm::ivec2 size_{0, 0};
    gl::Texture range_;
    gl::Framebuffer fbo_;
};

}  // namespace strata::peeling
