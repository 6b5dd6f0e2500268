#pragma once
// A program that draws scene meshes (shaders/common/scene.vert.glsl plus a fragment stage),
// with the locations of the per-pass and material uniforms looked up once (an object's own
// values are its record: render/object_records.hpp). A stage that
// does not use a uniform has location -1, which GL ignores, so one draw path serves all.
//
// Its variants are the same stages built with more defines, one per combination of what an
// object's draw needs beyond a factor-only material (SceneFeature): a stand-in (layered
// impostors, render/stand_in.hpp) wraps the fragment stage in the impostor alpha test; a base
// colour texture or vertex colours add their inputs and fetch (common/material.glsl); MASK
// wraps it in the alpha-cutoff test (common/scene_prelude.glsl, scene_main.glsl). A variant is
// built on its first draw; on its first draw of each pass, the uniforms the technique set on the
// program are copied onto it (variant()), so the technique never knows which drew. A factor-only material draws with the
// program itself: no texture fetch, no branch.
#include "gl/shader_program.hpp"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace strata {

// What a draw needs beyond the plain build; a bit set, the variant's key.
enum SceneFeature : unsigned {
    kSceneStandIn = 1u,                    // STRATA_IMPOSTOR
    kSceneBaseColorTexture = 2u,           // STRATA_BASE_COLOR_TEXTURE
    kSceneVertexColor = 4u,                // STRATA_VERTEX_COLOR
    kSceneAlphaMask = 8u,                  // STRATA_ALPHA_MASK
    kSceneMetallicRoughnessTexture = 16u,  // STRATA_METALLIC_ROUGHNESS_TEXTURE
    kSceneNormalTexture = 32u,             // STRATA_NORMAL_TEXTURE
    kSceneOcclusionTexture = 64u,          // STRATA_OCCLUSION_TEXTURE
    kSceneEmissiveTexture = 128u,          // STRATA_EMISSIVE_TEXTURE
    kSceneUnlit = 256u,                    // STRATA_UNLIT
    kScenePunctualLights = 512u,           // STRATA_PUNCTUAL_LIGHTS: the scene has its own lights
    kSceneTransmission = 1024u,            // STRATA_TRANSMISSION: KHR_materials_transmission, _ior
    kSceneFeatureCombinations = 2048u,     // one past every bit set
};

// A material's surface detail: its textures, vertex colours and MASK cut-out. Unlit and the
// light loop are not (they apply to stand-ins too).
inline constexpr unsigned kSceneSurfaceDetail = kSceneBaseColorTexture | kSceneVertexColor | kSceneAlphaMask |
                                                kSceneMetallicRoughnessTexture | kSceneNormalTexture |
                                                kSceneOcclusionTexture | kSceneEmissiveTexture;
// What a layered impostor bakes of it besides normals and depths (lod/layered_impostor.hpp's
// BakeMaterial): the base colour texture, COLOR_0 and the MASK cut. The rest (metallic-roughness,
// normal, occlusion and emissive textures) it does not, and --lod auto keeps such objects geometry.
inline constexpr unsigned kSceneBakedDetail = kSceneBaseColorTexture | kSceneVertexColor | kSceneAlphaMask;

// What a stand-in keeps of its object's draw: the factors and lights it shades with.
inline constexpr unsigned kSceneStandInKeeps = kSceneUnlit | kScenePunctualLights | kSceneTransmission;

// The locations of one material texture's uniforms (common/material.glsl).
struct TextureUniforms {
    GLint transform = -1, texCoord = -1;
};

struct SceneProgram {
    gl::Program program;
    // The material's and the pass's uniforms. The object's own values (transform, id, volume
    // entry and filter) are not uniforms: they come from its record (render/object_records.hpp).
    GLint viewProj = -1, baseColor = -1, alpha = -1, lightDir = -1, alphaCutoff = -1, tau = -1, albedo = -1,
          impostorSlices = -1, impostorOverlap = -1, impostorAlbedo = -1,  // common/scene_main.glsl (the variant's)
          metallic = -1, roughness = -1, emissive = -1, eye = -1, lightCount = -1,
          normalScale = -1, occlusionStrength = -1,  // common/material.glsl (the variant's)
          transmission = -1, ior = -1, alphaBlend = -1;
    // Base colour, metallic-roughness, normal, occlusion, emissive (GpuScene's MaterialSlot order).
    TextureUniforms textures[5];

    GLuint id() const { return program.id(); }

    // The variant for `features` (SceneFeature bits) with this program's current uniform values
    // (built on first use); `*this` for none. The values are copied on the variant's first use
    // after uniformsChanged(), not on every draw: a copy reads each uniform back (glGetUniform),
    // and a frame of 30,000 stand-ins spent 1.8 us of CPU on each of them on an NVIDIA H200
    // (docs/gpu-h200.md).
    const SceneProgram& variant(unsigned features) const;
    // Says that uniforms were set on this program since its variants last copied them.
    // GpuScene::setFrameUniforms calls it at the start of every pass; code that sets a uniform
    // of the program in the middle of a pass (none does) must call it too.
    void uniformsChanged() const { ++uniformGeneration_; }
    const SceneProgram& standInVariant() const { return variant(kSceneStandIn); }

    // What building the variant needs: the stages and defines this program was built from.
    std::vector<std::string> stages;
    gl::Defines defines;

private:
    // One uniform the technique may set, at its location in this program and in the variant.
    struct UniformCopy {
        GLint from = -1, to = -1;
        GLenum type = 0;
    };
    struct Variant;
    // Indexed by the feature bits; shared so that a copied SceneProgram keeps its variants.
    mutable std::shared_ptr<std::vector<std::shared_ptr<Variant>>> variants_;
    mutable std::uint64_t uniformGeneration_ = 0;
};

// Every scene program's fragment stage is wrapped by common/scene_prelude.glsl and
// common/scene_main.glsl (the impostor alpha test, in the STRATA_IMPOSTOR build only).
SceneProgram buildSceneProgram(const std::string& fragmentStage, const gl::Defines& defines = {});

// The wrap itself, for code that builds a scene program's stages by hand (tests).
gl::StageWrap sceneFragmentWrap();

// The same with the stages that follow the scene vertex stage given in full (a geometry stage,
// then the fragment stage).
SceneProgram buildSceneProgram(const std::vector<std::string>& laterStages, const gl::Defines& defines = {});

}  // namespace strata
