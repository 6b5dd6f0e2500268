#include "render/scene_program.hpp"

namespace strata {

SceneProgram buildSceneProgram(const std::string& fragmentStage, const gl::Defines& defines) {
    SceneProgram p;
    p.program = gl::buildProgram({"common/scene.vert.glsl", fragmentStage}, defines);
    GLuint id = p.program.id();
    p.viewProj = glGetUniformLocation(id, "uViewProj");
    p.model = glGetUniformLocation(id, "uModel");
    p.normalMatrix = glGetUniformLocation(id, "uNormalMatrix");
    p.baseColor = glGetUniformLocation(id, "uBaseColor");
    p.alpha = glGetUniformLocation(id, "uAlpha");
    p.objectId = glGetUniformLocation(id, "uObjectId");
    p.lightDir = glGetUniformLocation(id, "uLightDir");
    p.alphaCutoff = glGetUniformLocation(id, "uAlphaCutoff");
    p.tau = glGetUniformLocation(id, "uTau");
    p.albedo = glGetUniformLocation(id, "uAlbedo");
    return p;
}

}  // namespace strata
