#include "render/scene_program.hpp"

namespace strata {

gl::StageWrap sceneFragmentWrap() { return {"common/scene_prelude.glsl", "common/scene_main.glsl"}; }

SceneProgram buildSceneProgram(const std::string& fragmentStage, const gl::Defines& defines) {
    return buildSceneProgram(std::vector<std::string>{fragmentStage}, defines);
}

SceneProgram buildSceneProgram(const std::vector<std::string>& laterStages, const gl::Defines& defines) {
    std::vector<std::string> stages{"common/scene.vert.glsl"};
    stages.insert(stages.end(), laterStages.begin(), laterStages.end());
    SceneProgram p;
    p.program = gl::buildProgram(stages, defines, sceneFragmentWrap());
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
    p.volumeEntry = glGetUniformLocation(id, "uVolumeEntry");
    p.impostor = glGetUniformLocation(id, "uImpostor");
    p.impostorSlices = glGetUniformLocation(id, "uImpostorSlices");
    p.impostorOverlap = glGetUniformLocation(id, "uImpostorOverlap");
    return p;
}

}  // namespace strata
