#pragma once
// Saves the draw state a self-contained GPU job (an impostor bake, a start-up calibration)
// changes and puts it back when it goes out of scope, so the job can run in the middle of a
// frame or between a test's frames without the caller noticing.
#include <epoxy/gl.h>

namespace strata::gl {

class SavedDrawState {
public:
    SavedDrawState() {
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer_);
        glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readFramebuffer_);
        glGetIntegerv(GL_STENCIL_FUNC, &stencilFunc_);
        glGetIntegerv(GL_STENCIL_REF, &stencilRef_);
        glGetIntegerv(GL_STENCIL_VALUE_MASK, &stencilValueMask_);
        glGetIntegerv(GL_STENCIL_WRITEMASK, &stencilWriteMask_);
        glGetIntegerv(GL_STENCIL_FAIL, &stencilFail_);
        glGetIntegerv(GL_STENCIL_PASS_DEPTH_FAIL, &stencilDepthFail_);
        glGetIntegerv(GL_STENCIL_PASS_DEPTH_PASS, &stencilPass_);
        glGetIntegerv(GL_VIEWPORT, viewport_);
        glGetIntegerv(GL_CURRENT_PROGRAM, &program_);
        glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertexArray_);
        glGetIntegerv(GL_CLIP_ORIGIN, &clipOrigin_);
        glGetIntegerv(GL_CLIP_DEPTH_MODE, &clipDepth_);
        glGetIntegerv(GL_DEPTH_FUNC, &depthFunc_);
        glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask_);
        glGetBooleanv(GL_COLOR_WRITEMASK, colorMask_);
        glGetFloatv(GL_DEPTH_CLEAR_VALUE, &depthClear_);
        depthTest_ = glIsEnabled(GL_DEPTH_TEST);
        stencilTest_ = glIsEnabled(GL_STENCIL_TEST);
        scissorTest_ = glIsEnabled(GL_SCISSOR_TEST);
        blend_ = glIsEnabled(GL_BLEND);
        cull_ = glIsEnabled(GL_CULL_FACE);
    }
    ~SavedDrawState() {
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(framebuffer_));
        glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(readFramebuffer_));
        glStencilFunc(GLenum(stencilFunc_), stencilRef_, GLuint(stencilValueMask_));
        glStencilMask(GLuint(stencilWriteMask_));
        glStencilOp(GLenum(stencilFail_), GLenum(stencilDepthFail_), GLenum(stencilPass_));
        glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
        // A program or vertex array deleted while bound lived on only while bound: once the job
        // bound its own it is gone, and binding its name again would be an error.
        glUseProgram(glIsProgram(GLuint(program_)) ? GLuint(program_) : 0u);
        glBindVertexArray(glIsVertexArray(GLuint(vertexArray_)) ? GLuint(vertexArray_) : 0u);
        glClipControl(GLenum(clipOrigin_), GLenum(clipDepth_));
        glDepthFunc(GLenum(depthFunc_));
        glDepthMask(depthMask_);
        glColorMask(colorMask_[0], colorMask_[1], colorMask_[2], colorMask_[3]);
        glClearDepthf(depthClear_);
        set(GL_DEPTH_TEST, depthTest_);
        set(GL_STENCIL_TEST, stencilTest_);
        set(GL_SCISSOR_TEST, scissorTest_);
        set(GL_BLEND, blend_);
        set(GL_CULL_FACE, cull_);
    }
    SavedDrawState(const SavedDrawState&) = delete;
    SavedDrawState& operator=(const SavedDrawState&) = delete;

private:
    static void set(GLenum cap, GLboolean on) { on ? glEnable(cap) : glDisable(cap); }
    GLint framebuffer_ = 0, readFramebuffer_ = 0, viewport_[4] = {}, program_ = 0, vertexArray_ = 0;
    GLint stencilFunc_ = GL_ALWAYS, stencilRef_ = 0, stencilValueMask_ = -1, stencilWriteMask_ = -1;
    GLint stencilFail_ = GL_KEEP, stencilDepthFail_ = GL_KEEP, stencilPass_ = GL_KEEP;
    GLint clipOrigin_ = GL_LOWER_LEFT, clipDepth_ = GL_NEGATIVE_ONE_TO_ONE, depthFunc_ = GL_LESS;
    GLboolean depthMask_ = GL_TRUE, colorMask_[4] = {GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE};
    GLfloat depthClear_ = 1.0f;
    GLboolean depthTest_ = GL_FALSE, stencilTest_ = GL_FALSE, scissorTest_ = GL_FALSE, blend_ = GL_FALSE,
              cull_ = GL_FALSE;
};

}  // namespace strata::gl
