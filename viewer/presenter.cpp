#include "presenter.hpp"

#include "common/bindings.h"
#include "gl/shader_program.hpp"

namespace strata {
namespace {

gl::Program buildPresentProgram() {
    return gl::buildProgram({"common/fullscreen.vert.glsl", "frame/present.frag.glsl"});
}

}  // namespace

Presenter::Presenter() : emptyVertexArray_(gl::VertexArray::create()) { reload(); }

void Presenter::reload() {
    gl::Program next = buildPresentProgram();
    originLocation_ = glGetUniformLocation(next.id(), "uOrigin");
    program_ = std::move(next);
}

void Presenter::present(glm::ivec2 windowSize, std::span<const PresentRegion> regions) const {
    // Whatever state the frame left behind, the window gets exactly the encoded texels.
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, windowSize.x, windowSize.y);
    glDisable(GL_FRAMEBUFFER_SRGB);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    const float black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    glClearNamedFramebufferfv(0, GL_COLOR, 0, black);
    glUseProgram(program_.id());
    glBindVertexArray(emptyVertexArray_.id());
    for (const PresentRegion& region : regions) {
        glViewport(region.origin.x, region.origin.y, region.size.x, region.size.y);
        glProgramUniform2i(program_.id(), originLocation_, region.origin.x, region.origin.y);
        glBindTextureUnit(gpu::BIND_SOURCE, region.texture);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glViewport(0, 0, windowSize.x, windowSize.y);
    glBindVertexArray(0);
    glUseProgram(0);
}

}  // namespace strata
