#include "oit/peeling/object_skipper.hpp"

#include "oit/peeling/peel_bindings.hpp"

#include <glm/gtc/type_ptr.hpp>

#include <array>
#include <cmath>

namespace strata::peeling {

void ObjectSkipper::beginFrame(const FrameContext& frame, bool enabled) {
    enabled_ = enabled;
    std::size_t n = frame.scene.objects().size();
    culled_.assign(n, false);
    pending_.assign(n, Pending{});
    conditional_.clear();
    poolUsed_ = 0;
    boxDraws_ = 0;
}

GLuint ObjectSkipper::nextQuery() {
    if (poolUsed_ == pool_.size()) pool_.push_back(gl::createQuery(GL_ANY_SAMPLES_PASSED));
    return pool_[poolUsed_++].id();
}

void ObjectSkipper::ensureBox() {
    if (boxProgram_) return;
    boxProgram_ = gl::buildProgram({"oit/peeling/bounds.vert.glsl", "oit/peeling/bounds_query.frag.glsl"});
    boxMin_ = glGetUniformLocation(boxProgram_.id(), "uBoxMin");
    boxMax_ = glGetUniformLocation(boxProgram_.id(), "uBoxMax");
    boxViewProj_ = glGetUniformLocation(boxProgram_.id(), "uViewProj");
    boxSide_ = glGetUniformLocation(boxProgram_.id(), "uSide");
    const std::array<float, 24> corners = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
    const std::array<GLuint, 36> indices = {0, 1, 2, 0, 2, 3, 4, 6, 5, 4, 7, 6, 0, 4, 5, 0, 5, 1,
                                            3, 2, 6, 3, 6, 7, 0, 3, 7, 0, 7, 4, 1, 5, 6, 1, 6, 2};
    boxVao_ = gl::VertexArray::create();
    boxVertices_ = gl::Buffer::create();
    boxIndices_ = gl::Buffer::create();
    glNamedBufferStorage(boxVertices_.id(), sizeof(corners), corners.data(), 0);
    glNamedBufferStorage(boxIndices_.id(), sizeof(indices), indices.data(), 0);
    GLuint vao = boxVao_.id();
    glVertexArrayVertexBuffer(vao, 0, boxVertices_.id(), 0, 3 * sizeof(float));
    glVertexArrayElementBuffer(vao, boxIndices_.id());
    glEnableVertexArrayAttrib(vao, 0);
    glVertexArrayAttribFormat(vao, 0, 3, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(vao, 0, 0);
}

void ObjectSkipper::query(const FrameContext& frame, GLuint remaining, const std::vector<RemainingSide>& sides) {
    if (!enabled_) return;
    ensureBox();
    gl::ScopedPass pass(frame.timer, "skip queries");
    // The output framebuffer only gives the boxes somewhere to rasterize: nothing is written
    // (colour masked, no depth test or writes) and none of the peel textures is attached.
    glBindFramebuffer(GL_FRAMEBUFFER, frame.targets.outputFramebuffer());
    glViewport(0, 0, frame.size.x, frame.size.y);
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    // Parts of a box in front of the near plane (the eye inside it) or past the far plane still
    // rasterize, clamped, so the test stays conservative.
    glEnable(GL_DEPTH_CLAMP);
    // The unit cube's triangles (ensureBox) wind clockwise seen from outside.
    glFrontFace(GL_CW);
    glUseProgram(boxProgram_.id());
    glProgramUniformMatrix4fv(boxProgram_.id(), boxViewProj_, 1, GL_FALSE, glm::value_ptr(frame.viewProjection));
    glBindTextureUnit(peel_bindings::kPrevious, remaining);
    glBindVertexArray(boxVao_.id());
    const auto& objects = frame.scene.objects();
    for (int o : frame.transparentOrder) {
        if (culled_[o]) continue;
        const Bounds& b = objects[o].worldBounds;
        if (b.empty()) continue;
        // Inflated so that the box's faces are never rasterized nearer than a surface lying on
        // them (a flat quad has a flat box) and its outline covers every pixel the object does.
        glm::vec3 extent = b.max - b.min;
        float pad = 1e-4f * glm::length(extent) + 1e-6f * (1.0f + glm::length(b.center()));
        glm::vec3 lo = b.min - pad, hi = b.max + pad;
        glProgramUniform3fv(boxProgram_.id(), boxMin_, 1, glm::value_ptr(lo));
        glProgramUniform3fv(boxProgram_.id(), boxMax_, 1, glm::value_ptr(hi));
        // Seen from outside, each pixel the box covers has one near and one far face, and the
        // witness for each side is on one of them: the far face holds the box's farthest point
        // (side 0: is anything not nearer than r?), the near face its nearest (side 1). So only
        // that face is drawn, half the fragments. With the eye inside the box there are no near
        // faces in front of it: then both are drawn, as the depth clamp makes them count.
        const glm::vec3 eye = frame.camera.position;
        const bool eyeInside = glm::all(glm::greaterThanEqual(eye, lo)) && glm::all(glm::lessThanEqual(eye, hi));
        auto& pending = pending_[o].queries;
        pending.clear();
        for (RemainingSide side : sides) {
            GLuint q = nextQuery();
            if (eyeInside) {
                glDisable(GL_CULL_FACE);
            } else {
                glEnable(GL_CULL_FACE);
                glCullFace(side == RemainingSide::NotNearerThanR ? GL_FRONT : GL_BACK);
            }
            glProgramUniform1i(boxProgram_.id(), boxSide_, side == RemainingSide::NotNearerThanR ? 0 : 1);
            glBeginQuery(GL_ANY_SAMPLES_PASSED, q);
            glDrawElements(GL_TRIANGLES, 36, GL_UNSIGNED_INT, nullptr);
            glEndQuery(GL_ANY_SAMPLES_PASSED);
            pending.push_back(q);
            ++boxDraws_;
        }
    }
    glDisable(GL_DEPTH_CLAMP);
    glDisable(GL_CULL_FACE);
    glFrontFace(GL_CCW);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

void ObjectSkipper::draw(const FrameContext& frame, const SceneProgram& program, TechniqueStats& stats) {
    glUseProgram(program.id());
    frame.scene.setFrameUniforms(program, frame.viewProjection);
    for (int o : frame.transparentOrder) {
        if (!enabled_) {
            frame.scene.draw(program, o);
            ++stats.objectDraws;
            continue;
        }
        if (culled_[o]) {
            ++stats.objectDrawsSkipped;
            continue;
        }
        auto& pending = pending_[o].queries;
        // Results already on the CPU decide without waiting; the first unknown one is left to
        // the GPU through conditional rendering.
        GLuint unknown = 0;
        bool behind = false;
        for (GLuint q : pending) {
            GLuint available = 0;
            glGetQueryObjectuiv(q, GL_QUERY_RESULT_AVAILABLE, &available);
            if (!available) {
                if (!unknown) unknown = q;
                continue;
            }
            GLuint passed = 0;
            glGetQueryObjectuiv(q, GL_QUERY_RESULT, &passed);
            if (!passed) behind = true;
        }
        if (behind) {
            culled_[o] = true;
            pending.clear();
            ++stats.objectDrawsSkipped;
            continue;
        }
        ++stats.objectDraws;
        if (unknown) {
            glBeginConditionalRender(unknown, GL_QUERY_WAIT);
            frame.scene.draw(program, o);
            glEndConditionalRender();
            conditional_.push_back({unknown});
        } else {
            frame.scene.draw(program, o);
        }
    }
}

void ObjectSkipper::endFrame(TechniqueStats& stats) {
    for (const Conditional& c : conditional_) {
        GLuint passed = 0;
        glGetQueryObjectuiv(c.query, GL_QUERY_RESULT, &passed);
        if (!passed) {
            --stats.objectDraws;
            ++stats.objectDrawsSkipped;
        }
    }
    conditional_.clear();
}

}  // namespace strata::peeling
