#pragma once
// A program that draws scene meshes (shaders/common/scene.vert.glsl plus a fragment stage),
// with the locations of the per-frame and per-object uniforms looked up once. A stage that
// does not use a uniform has location -1, which GL ignores, so one draw path serves all.
#include "gl/shader_program.hpp"

#include <string>
#include <vector>

namespace strata {

struct SceneProgram {
    gl::Program program;
    GLint viewProj = -1, model = -1, normalMatrix = -1, baseColor = -1, alpha = -1, objectId = -1,
          lightDir = -1, alphaCutoff = -1, tau = -1, albedo = -1,
          volumeEntry = -1,  // shaders/oit/volume/volume_store.glsl
          impostor = -1, impostorSlices = -1, impostorOverlap = -1;  // common/scene_main.glsl

    GLuint id() const { return program.id(); }
};

// Every scene program's fragment stage is wrapped by common/scene_prelude.glsl and
// common/scene_main.glsl: the layered-impostor alpha test runs before the stage's own main()
// (render/stand_in.hpp).
SceneProgram buildSceneProgram(const std::string& fragmentStage, const gl::Defines& defines = {});

// The wrap itself, for code that builds a scene program's stages by hand (tests).
gl::StageWrap sceneFragmentWrap();

// The same with the stages that follow the scene vertex stage given in full (a geometry stage,
// then the fragment stage).
SceneProgram buildSceneProgram(const std::vector<std::string>& laterStages, const gl::Defines& defines = {});

}  // namespace strata
