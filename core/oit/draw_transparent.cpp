#include "oit/draw_transparent.hpp"

#include "render/depth_order.hpp"

#include <algorithm>

namespace strata {

void setTransparentDepthState(const FrameContext& frame) {
    glViewport(0, 0, frame.size.x, frame.size.y);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);
    glDepthMask(GL_FALSE);
    glDisable(GL_CULL_FACE);
}

std::uint64_t drawTransparent(const FrameContext& frame, const SceneProgram& program, const std::vector<int>& order) {
    glUseProgram(program.id());
    frame.scene.setFrameUniforms(program, frame.viewProjection);
    frame.drawAll(program, order);
    return order.size();
}

void drawFullscreenAsSet(const FrameContext& frame, GLuint program) {
    glUseProgram(program);
    glBindVertexArray(frame.targets.emptyVertexArray());
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

PixelRect transparentAreaWithin(const FrameContext& frame, const PixelRect& within) {
    return frame.transparentArea ? within.intersect(*frame.transparentArea) : within;
}

TransparentAreaScissor::TransparentAreaScissor(const FrameContext& frame, std::optional<PixelRect> within)
    : on_(frame.transparentArea.has_value() || within.has_value()) {
    if (!on_) return;
    const PixelRect area = within ? transparentAreaWithin(frame, *within) : *frame.transparentArea;
    glEnable(GL_SCISSOR_TEST);
    glScissor(area.origin.x, area.origin.y, area.size.x, area.size.y);
}

TransparentAreaScissor::~TransparentAreaScissor() {
    if (on_) glDisable(GL_SCISSOR_TEST);
}

MaskedDrawBuffers::MaskedDrawBuffers(std::vector<GLuint> buffers) : buffers_(std::move(buffers)) {
    for (GLuint i : buffers_) glColorMaski(i, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
}

MaskedDrawBuffers::~MaskedDrawBuffers() {
    for (GLuint i : buffers_) glColorMaski(i, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

void drawFullscreen(const FrameContext& frame, GLuint program) {
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    drawFullscreenAsSet(frame, program);
}

void drawFullscreenDepth(const FrameContext& frame, GLuint program) {
    glViewport(0, 0, frame.size.x, frame.size.y);
    glDisable(GL_BLEND);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_TRUE);
    drawFullscreenAsSet(frame, program);
    glDepthMask(GL_FALSE);
}

void setDepthOrderUniforms(const FrameContext& frame, GLuint program) {
    const double n = frame.camera.nearPlane, f = frame.camera.farPlane;
    glProgramUniform1f(program, glGetUniformLocation(program, "uDepthOffset"), float(n / (f - n)));
    glProgramUniform1f(program, glGetUniformLocation(program, "uTieTolerance"),
                       float(tieToleranceFromUlps(frame.scene.scene().depthTieUlps)));
}

std::vector<int> sortedBackToFront(const FrameContext& frame) {
    std::vector<int> order = frame.transparentOrder;
    glm::vec3 eye = frame.camera.position;
    glm::vec3 forward = frame.camera.forward();
    auto viewDepth = [&](int i) { return glm::dot(frame.boundsOf(i).center() - eye, forward); };
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return viewDepth(a) > viewDepth(b); });
    return order;
}

}  // namespace strata
