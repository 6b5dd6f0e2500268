#include "render/scene_program.hpp"

#include <cstdio>
#include <set>
#include <stdexcept>

namespace strata {
namespace {

SceneProgram buildFromStages(std::vector<std::string> stages, gl::Defines defines) {
    SceneProgram p;
    p.program = gl::buildProgram(stages, defines, sceneFragmentWrap());
    p.stages = std::move(stages);
    p.defines = std::move(defines);
    GLuint id = p.program.id();
    p.viewProj = glGetUniformLocation(id, "uViewProj");
    p.baseColor = glGetUniformLocation(id, "uBaseColor");
    p.alpha = glGetUniformLocation(id, "uAlpha");
    p.lightDir = glGetUniformLocation(id, "uLightDir");
    p.alphaCutoff = glGetUniformLocation(id, "uAlphaCutoff");
    p.tau = glGetUniformLocation(id, "uTau");
    p.albedo = glGetUniformLocation(id, "uAlbedo");
    p.impostorSlices = glGetUniformLocation(id, "uImpostorSlices");
    p.impostorOverlap = glGetUniformLocation(id, "uImpostorOverlap");
    p.impostorAlbedo = glGetUniformLocation(id, "uImpostorAlbedo");
    p.metallic = glGetUniformLocation(id, "uMetallic");
    p.roughness = glGetUniformLocation(id, "uRoughness");
    p.emissive = glGetUniformLocation(id, "uEmissive");
    p.eye = glGetUniformLocation(id, "uEye");
    p.lightCount = glGetUniformLocation(id, "uLightCount");
    p.normalScale = glGetUniformLocation(id, "uNormalScale");
    p.occlusionStrength = glGetUniformLocation(id, "uOcclusionStrength");
    p.transmission = glGetUniformLocation(id, "uTransmission");
    p.ior = glGetUniformLocation(id, "uIor");
    p.alphaBlend = glGetUniformLocation(id, "uAlphaBlend");
    const char* slots[5] = {"BaseColor", "MetallicRoughness", "Normal", "Occlusion", "Emissive"};
    for (int i = 0; i < 5; ++i) {
        p.textures[i].transform = glGetUniformLocation(id, ("u" + std::string(slots[i]) + "Transform").c_str());
        p.textures[i].texCoord = glGetUniformLocation(id, ("u" + std::string(slots[i]) + "TexCoord").c_str());
    }
    return p;
}

// The uniform types standInVariant copies by value (the switch below).
bool copyable(GLenum type) {
    switch (type) {
    case GL_FLOAT: case GL_FLOAT_VEC2: case GL_FLOAT_VEC3: case GL_FLOAT_VEC4: case GL_FLOAT_MAT3: case GL_FLOAT_MAT4:
    case GL_INT: case GL_INT_VEC2: case GL_INT_VEC3: case GL_INT_VEC4:
    case GL_BOOL: case GL_BOOL_VEC2: case GL_BOOL_VEC3: case GL_BOOL_VEC4:
    case GL_UNSIGNED_INT: case GL_UNSIGNED_INT_VEC2: case GL_UNSIGNED_INT_VEC3: case GL_UNSIGNED_INT_VEC4:
        return true;
    default: return false;
    }
}

// Samplers, images and atomic counters: both programs take them from layout(binding).
bool boundByLayout(GLenum type) {
    switch (type) {
    case GL_SAMPLER_2D: case GL_SAMPLER_2D_ARRAY: case GL_SAMPLER_2D_MULTISAMPLE: case GL_SAMPLER_3D:
    case GL_SAMPLER_2D_SHADOW: case GL_UNSIGNED_INT_SAMPLER_2D: case GL_UNSIGNED_INT_SAMPLER_2D_ARRAY:
    case GL_INT_SAMPLER_2D: case GL_UNSIGNED_INT_SAMPLER_BUFFER: case GL_SAMPLER_BUFFER:
    case GL_IMAGE_2D: case GL_IMAGE_2D_ARRAY: case GL_UNSIGNED_INT_IMAGE_2D: case GL_UNSIGNED_INT_IMAGE_2D_ARRAY:
    case GL_INT_IMAGE_2D: case GL_UNSIGNED_INT_IMAGE_BUFFER: case GL_UNSIGNED_INT_ATOMIC_COUNTER:
        return true;
    default: return false;
    }
}

std::string hex(GLenum value) {
    char text[16];
    std::snprintf(text, sizeof text, "%x", unsigned(value));
    return text;
}

}  // namespace

struct SceneProgram::Variant {
    SceneProgram program;
    std::vector<UniformCopy> copies;
    std::uint64_t copiedGeneration = ~std::uint64_t(0);  // none yet
};

gl::StageWrap sceneFragmentWrap() { return {"common/scene_prelude.glsl", "common/scene_main.glsl"}; }

SceneProgram buildSceneProgram(const std::string& fragmentStage, const gl::Defines& defines) {
    return buildSceneProgram(std::vector<std::string>{fragmentStage}, defines);
}

SceneProgram buildSceneProgram(const std::vector<std::string>& laterStages, const gl::Defines& defines) {
    std::vector<std::string> stages{"common/scene.vert.glsl"};
    stages.insert(stages.end(), laterStages.begin(), laterStages.end());
    return buildFromStages(std::move(stages), defines);
}

const SceneProgram& SceneProgram::variant(unsigned features) const {
    if (features == 0) return *this;
    constexpr unsigned kCombinations = kSceneFeatureCombinations;
    if (features >= kCombinations) throw std::logic_error("scene program: unknown feature bits");
    if (!variants_) variants_ = std::make_shared<std::vector<std::shared_ptr<Variant>>>(kCombinations);
    std::shared_ptr<Variant>& slot = (*variants_)[features];
    if (!slot) {
        auto v = std::make_shared<Variant>();
        gl::Defines defines = this->defines;
        if (features & kSceneStandIn) defines["STRATA_IMPOSTOR"] = "";
        if (features & kSceneBaseColorTexture) defines["STRATA_BASE_COLOR_TEXTURE"] = "";
        if (features & kSceneVertexColor) defines["STRATA_VERTEX_COLOR"] = "";
        if (features & kSceneAlphaMask) defines["STRATA_ALPHA_MASK"] = "";
        if (features & kSceneMetallicRoughnessTexture) defines["STRATA_METALLIC_ROUGHNESS_TEXTURE"] = "";
        if (features & kSceneNormalTexture) defines["STRATA_NORMAL_TEXTURE"] = "";
        if (features & kSceneOcclusionTexture) defines["STRATA_OCCLUSION_TEXTURE"] = "";
        if (features & kSceneEmissiveTexture) defines["STRATA_EMISSIVE_TEXTURE"] = "";
        if (features & kSceneUnlit) defines["STRATA_UNLIT"] = "";
        if (features & kScenePunctualLights) defines["STRATA_PUNCTUAL_LIGHTS"] = "";
        if (features & kSceneTransmission) defines["STRATA_TRANSMISSION"] = "";
        v->program = buildFromStages(stages, defines);
        // Every plain uniform of this program except the material's, which GpuScene sets on
        // whichever program draws (samplers, images and blocks bind by layout, not by value; the
        // object's own values are its record, not uniforms).
        const std::set<std::string> perObject = {
            "uBaseColor", "uAlpha", "uAlphaCutoff", "uTau", "uAlbedo", "uMetallic", "uRoughness", "uEmissive", "uNormalScale", "uOcclusionStrength",
            "uBaseColorTransform", "uBaseColorTexCoord", "uMetallicRoughnessTransform", "uMetallicRoughnessTexCoord",
            "uNormalTransform", "uNormalTexCoord", "uOcclusionTransform", "uOcclusionTexCoord",
            "uEmissiveTransform", "uEmissiveTexCoord"};
        GLint count = 0;
        glGetProgramiv(id(), GL_ACTIVE_UNIFORMS, &count);
        for (GLint i = 0; i < count; ++i) {
            char name[256];
            GLint size = 0;
            GLenum type = 0;
            glGetActiveUniform(id(), GLuint(i), sizeof name, nullptr, &size, &type, name);
            std::string base = name;
            if (auto bracket = base.find('['); bracket != std::string::npos) base.resize(bracket);
            if (perObject.count(base)) continue;
            if (!copyable(type) && !boundByLayout(type))
                throw std::runtime_error("scene program " + stages.back() + ": uniform " + base +
                                         " has a type the stand-in variant cannot copy (0x" + hex(type) + ")");
            for (GLint element = 0; element < size; ++element) {
                const std::string at = size > 1 ? base + "[" + std::to_string(element) + "]" : std::string(name);
                UniformCopy c{glGetUniformLocation(id(), at.c_str()),
                              glGetUniformLocation(v->program.id(), at.c_str()), type};
                if (c.from >= 0 && c.to >= 0) v->copies.push_back(c);
            }
        }
        slot = std::move(v);
    }
    Variant& built = *slot;
    if (built.copiedGeneration == uniformGeneration_) return built.program;
    built.copiedGeneration = uniformGeneration_;
    const GLuint from = id(), to = built.program.id();
    for (const UniformCopy& c : built.copies) {
        GLfloat f[16];
        GLint i[4];
        GLuint u[4];
        switch (c.type) {
        case GL_FLOAT: glGetUniformfv(from, c.from, f); glProgramUniform1fv(to, c.to, 1, f); break;
        case GL_FLOAT_VEC2: glGetUniformfv(from, c.from, f); glProgramUniform2fv(to, c.to, 1, f); break;
        case GL_FLOAT_VEC3: glGetUniformfv(from, c.from, f); glProgramUniform3fv(to, c.to, 1, f); break;
        case GL_FLOAT_VEC4: glGetUniformfv(from, c.from, f); glProgramUniform4fv(to, c.to, 1, f); break;
        case GL_FLOAT_MAT3: glGetUniformfv(from, c.from, f); glProgramUniformMatrix3fv(to, c.to, 1, GL_FALSE, f); break;
        case GL_FLOAT_MAT4: glGetUniformfv(from, c.from, f); glProgramUniformMatrix4fv(to, c.to, 1, GL_FALSE, f); break;
        case GL_INT: case GL_BOOL: glGetUniformiv(from, c.from, i); glProgramUniform1iv(to, c.to, 1, i); break;
        case GL_INT_VEC2: case GL_BOOL_VEC2: glGetUniformiv(from, c.from, i); glProgramUniform2iv(to, c.to, 1, i); break;
        case GL_INT_VEC3: case GL_BOOL_VEC3: glGetUniformiv(from, c.from, i); glProgramUniform3iv(to, c.to, 1, i); break;
        case GL_INT_VEC4: case GL_BOOL_VEC4: glGetUniformiv(from, c.from, i); glProgramUniform4iv(to, c.to, 1, i); break;
        case GL_UNSIGNED_INT: glGetUniformuiv(from, c.from, u); glProgramUniform1uiv(to, c.to, 1, u); break;
        case GL_UNSIGNED_INT_VEC2: glGetUniformuiv(from, c.from, u); glProgramUniform2uiv(to, c.to, 1, u); break;
        case GL_UNSIGNED_INT_VEC3: glGetUniformuiv(from, c.from, u); glProgramUniform3uiv(to, c.to, 1, u); break;
        case GL_UNSIGNED_INT_VEC4: glGetUniformuiv(from, c.from, u); glProgramUniform4uiv(to, c.to, 1, u); break;
        default: break;  // samplers, images, atomic counters: bound by layout(binding) in both
        }
    }
    return built.program;
}

}  // namespace strata
