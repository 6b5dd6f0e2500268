#include "oit/peeling/bucket_range.hpp"

#include "oit/draw_transparent.hpp"

#include <glm/gtc/type_ptr.hpp>

#include <array>

namespace strata::peeling {

void BucketRange::ensure(glm::ivec2 size) {
    if (!geometryProgram_.program) {
        geometryProgram_ = buildSceneProgram("oit/peeling/bun_range.frag.glsl");
        boxProgram_ = gl::buildProgram({"oit/peeling/bounds.vert.glsl", "oit/peeling/bun_range.frag.glsl"});
        const std::array<float, 24> corners = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
        const std::array<GLuint, 36> indices = {0, 1, 2, 0, 2, 3, 4, 6, 5, 4, 7, 6, 0, 4, 5, 0, 5, 1,
                                                3, 2, 6, 3, 6, 7, 0, 3, 7, 0, 7, 4, 1, 5, 6, 1, 6, 2};
        boxVao_ = gl::VertexArray::create();
        boxVertices_ = gl::Buffer::create();
        boxIndices_ = gl::Buffer::create();
        glNamedBufferStorage(boxVertices_.id(), sizeof(corners), corners.data(), 0);
        glNamedBufferStorage(boxIndices_.id(), sizeof(indices), indices.data(), 0);
        glVertexArrayVertexBuffer(boxVao_.id(), 0, boxVertices_.id(), 0, 3 * sizeof(float));
        glVertexArrayElementBuffer(boxVao_.id(), boxIndices_.id());
        glEnableVertexArrayAttrib(boxVao_.id(), 0);
        glVertexArrayAttribFormat(boxVao_.id(), 0, 3, GL_FLOAT, GL_FALSE, 0);
        glVertexArrayAttribBinding(boxVao_.id(), 0, 0);
    }
    if (size == size_) return;
    size_ = size;
    range_ = gl::createTexture2D(GL_RG32F, size.x, size.y);
    fbo_ = gl::Framebuffer::create();
    glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, range_.id(), 0);
}

void BucketRange::render(const FrameContext& frame, bool fromGeometry, TechniqueStats& stats) {
    ensure(frame.size);
    const float clearRange[4] = {-2, -2, 0, 0};
    glClearTexImage(range_.id(), 0, GL_RGBA, GL_FLOAT, clearRange);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glViewport(0, 0, frame.size.x, frame.size.y);
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendEquation(GL_MAX);
    if (fromGeometry) {
        stats.objectDraws += drawTransparent(frame, geometryProgram_, frame.transparentOrder);
    } else {
        // Boxes crossing the near plane (the eye inside) rasterize clamped at depth 1.
        glEnable(GL_DEPTH_CLAMP);
        GLuint p = boxProgram_.id();
        glUseProgram(p);
        glProgramUniformMatrix4fv(p, glGetUniformLocation(p, "uViewProj"), 1, GL_FALSE,
                                  glm::value_ptr(frame.viewProjection));
        glBindVertexArray(boxVao_.id());
        for (int o : frame.transparentOrder) {
            const Bounds& b = frame.boundsOf(o);
            if (b.empty()) continue;
            glProgramUniform3fv(p, glGetUniformLocation(p, "uBoxMin"), 1, glm::value_ptr(b.min));
            glProgramUniform3fv(p, glGetUniformLocation(p, "uBoxMax"), 1, glm::value_ptr(b.max));
            glDrawElements(GL_TRIANGLES, 36, GL_UNSIGNED_INT, nullptr);
        }
        glDisable(GL_DEPTH_CLAMP);
    }
    glBlendEquation(GL_FUNC_ADD);
    glDisable(GL_BLEND);
    ++stats.passes;
}

}  // namespace strata::peeling
