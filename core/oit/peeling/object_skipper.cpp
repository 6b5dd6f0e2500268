#include "oit/peeling/object_skipper.hpp"

#include "oit/peeling/peel_bindings.h"
#include "render/screen_rect.hpp"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>

namespace strata::peeling {

void ObjectSkipper::beginFrame(const FrameContext& frame, bool enabled) {
    enabled_ = enabled;
    std::size_t n = frame.scene.objects().size();
    culled_.assign(n, false);
    pending_.assign(n, Pending{});
    conditional_.clear();
    poolUsed_ = 0;
    queryDraws_ = 0;
    boxes_.clear();  // projected on the frame's first query: the camera is fixed within a frame
}

GLuint ObjectSkipper::nextQuery() {
    if (poolUsed_ == pool_.size()) pool_.push_back(gl::createQuery(GL_ANY_SAMPLES_PASSED));
    return pool_[poolUsed_++].id();
}

void ObjectSkipper::ensurePrograms() {
    if (reduceProgram_) return;
    reduceProgram_ = gl::buildProgram({"common/fullscreen.vert.glsl", "oit/peeling/bound_reduce.frag.glsl"});
    reduceNearProgram_ = gl::buildProgram({"common/fullscreen.vert.glsl", "oit/peeling/bound_reduce.frag.glsl"},
                                          {{"NEAR_BOUND_ONLY", ""}});
    rectProgram_ = gl::buildProgram({"oit/peeling/bounds_rect.vert.glsl", "oit/peeling/bounds_query.frag.glsl"});
    rectLocation_ = glGetUniformLocation(rectProgram_.id(), "uRect");
    sidesLocation_ = glGetUniformLocation(rectProgram_.id(), "uSides");
    boxFarLocation_ = glGetUniformLocation(rectProgram_.id(), "uBoxFar");
    boxNearLocation_ = glGetUniformLocation(rectProgram_.id(), "uBoxNear");
    for (const gl::Program* p : {&reduceProgram_, &reduceNearProgram_})
        glProgramUniform1i(p->id(), glGetUniformLocation(p->id(), "uBlock"), kBlock);
    emptyVao_ = gl::VertexArray::create();
}

void ObjectSkipper::ensureReducedTarget(glm::ivec2 size) {
    const glm::ivec2 reduced = (size + kBlock - 1) / kBlock;
    if (reduced == reducedSize_) return;
    reducedSize_ = reduced;
    reduced_ = gl::createTexture2D(GL_RG32F, reduced.x, reduced.y);
    reduceFbo_ = gl::Framebuffer::create();
    glNamedFramebufferTexture(reduceFbo_.id(), GL_COLOR_ATTACHMENT0, reduced_.id(), 0);
    // The queries rasterize into a framebuffer with no attachments, so the reduced bound they
    // sample is never also a render target.
    queryFbo_ = gl::Framebuffer::create();
    glNamedFramebufferParameteri(queryFbo_.id(), GL_FRAMEBUFFER_DEFAULT_WIDTH, reduced.x);
    glNamedFramebufferParameteri(queryFbo_.id(), GL_FRAMEBUFFER_DEFAULT_HEIGHT, reduced.y);
}

ObjectSkipper::ScreenBox ObjectSkipper::screenBox(const FrameContext& frame, const Bounds& b) const {
    const ScreenProjection p = projectBox(frame.viewProjection, b);
    ScreenBox box;
    // Whole reduced pixels covering the rectangle, with one more on each side for round-off (a
    // box reaching behind the eye: all of them, and the whole depth range, which never culls).
    box.blocks = pixelRect(p, frame.size, kBlock);
    if (p.behindEye) return box;
    box.farDepth = p.farDepth;
    box.nearDepth = p.nearDepth;
    box.empty = box.blocks.empty();
    const glm::vec2 reduced(reducedSize_);
    const glm::vec2 t0(box.blocks.origin), t1(box.blocks.origin + box.blocks.size);
    box.rect = glm::vec4(t0 / reduced * 2.0f - 1.0f, t1 / reduced * 2.0f - 1.0f);
    return box;
}

void ObjectSkipper::query(const FrameContext& frame, GLuint remaining, const std::vector<RemainingSide>& sides) {
    if (!enabled_) return;
    ensurePrograms();
    ensureReducedTarget(frame.size);
    gl::ScopedPass pass(frame.timer, "skip queries");
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glBindVertexArray(emptyVao_.id());

    const auto& objects = frame.scene.objects();
    if (boxes_.empty()) {
        boxes_.resize(objects.size());
        queriedBlocks_ = PixelRect{};
        for (int o : frame.transparentOrder) {
            if (frame.boundsOf(o).empty()) continue;
            boxes_[o] = screenBox(frame, frame.boundsOf(o));
            if (!boxes_[o].empty) queriedBlocks_ = queriedBlocks_.unite(boxes_[o].blocks);
        }
    }

    // The bound's block maxima: one small pass instead of a full-resolution box per object,
    // over the blocks some object's rectangle covers (no query reads the others; on llvmpipe a
    // block costs its 64 texel reads wherever it lies).
    glBindFramebuffer(GL_FRAMEBUFFER, reduceFbo_.id());
    glViewport(0, 0, reducedSize_.x, reducedSize_.y);
    glBindTextureUnit(gpu::BIND_PEEL_PREVIOUS, remaining);
    int sideBits = 0;
    for (RemainingSide side : sides) sideBits |= side == RemainingSide::NotNearerThanR ? 1 : 2;
    // A bound whose g no query reads is reduced in r alone (half the texel reads).
    glUseProgram((sideBits == 1 ? reduceNearProgram_ : reduceProgram_).id());
    if (!queriedBlocks_.empty()) {
        glEnable(GL_SCISSOR_TEST);
        glScissor(queriedBlocks_.origin.x, queriedBlocks_.origin.y, queriedBlocks_.size.x, queriedBlocks_.size.y);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glDisable(GL_SCISSOR_TEST);
    }
    // No memory barrier: the rectangles sample what was just rendered, which GL orders itself.

    // One rectangle per live object, under an occlusion query.
    glBindFramebuffer(GL_FRAMEBUFFER, queryFbo_.id());
    glBindTextureUnit(gpu::BIND_PEEL_PREVIOUS, reduced_.id());
    const GLuint program = rectProgram_.id();
    glUseProgram(program);
    glProgramUniform1i(program, sidesLocation_, sideBits);
    for (int o : frame.transparentOrder) {
        if (culled_[o] || frame.boundsOf(o).empty()) continue;
        const ScreenBox& box = boxes_[o];
        glProgramUniform4fv(program, rectLocation_, 1, glm::value_ptr(box.rect));
        glProgramUniform1f(program, boxFarLocation_, box.farDepth);
        glProgramUniform1f(program, boxNearLocation_, box.nearDepth);
        const GLuint q = nextQuery();
        // An empty rectangle (the object off screen) draws nothing: the query reads 0.
        glBeginQuery(GL_ANY_SAMPLES_PASSED, q);
        if (!box.empty) glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
        glEndQuery(GL_ANY_SAMPLES_PASSED);
        pending_[o].query = q;
        ++queryDraws_;
    }
    glViewport(0, 0, frame.size.x, frame.size.y);
}

void ObjectSkipper::draw(const FrameContext& frame, const SceneProgram& program, TechniqueStats& stats) {
    glUseProgram(program.id());
    frame.scene.setFrameUniforms(program, frame.viewProjection);
    if (!enabled_) {
        frame.drawAll(program, frame.transparentOrder);
        stats.objectDraws += frame.transparentOrder.size();
        return;
    }
    // The objects that draw without a condition go out together (instanced where they share a
    // mesh), in submission order up to each conditional draw.
    unconditional_.clear();
    auto flush = [&] {
        frame.drawAll(program, unconditional_);
        unconditional_.clear();
    };
    for (int o : frame.transparentOrder) {
        if (culled_[o]) {
            ++stats.objectDrawsSkipped;
            continue;
        }
        // A result already on the CPU decides without waiting; an unknown one is left to the GPU
        // through conditional rendering.
        GLuint& pending = pending_[o].query;
        GLuint unknown = 0;
        if (pending) {
            GLuint available = 0;
            glGetQueryObjectuiv(pending, GL_QUERY_RESULT_AVAILABLE, &available);
            if (available) {
                GLuint passed = 0;
                glGetQueryObjectuiv(pending, GL_QUERY_RESULT, &passed);
                if (!passed) {
                    culled_[o] = true;
                    pending = 0;
                    ++stats.objectDrawsSkipped;
                    continue;
                }
            } else {
                unknown = pending;
            }
        }
        ++stats.objectDraws;
        if (unknown) {
            flush();
            glBeginConditionalRender(unknown, GL_QUERY_WAIT);
            frame.draw(program, o);
            glEndConditionalRender();
            conditional_.push_back({unknown});
        } else {
            unconditional_.push_back(o);
        }
    }
    flush();
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
