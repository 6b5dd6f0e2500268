#include "oit/screendoor/point_samples.hpp"

#include "common/bindings.h"
#include "gl/shader_program.hpp"
#include "oit/screendoor/screendoor_bindings.h"
#include "render/gpu_scene.hpp"
#include "render/scene_program.hpp"
#include "render/shading.hpp"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <vector>

namespace strata::screendoor {

namespace {
constexpr std::uint64_t kInitialPoints = 1u << 16;

// The probability a point is kept: the factor alpha, or for transmissive glass its scalar form
// (common/shading_model.h's scalarOpacityForm) seen head on: the points have one alpha per
// object, so the Fresnel rise at grazing angles and the filter's tint are not drawn.
float keepProbability(const Material& m) {
    if (!m.transmissive()) return m.alpha;
    const float coverage = m.alphaMode == AlphaMode::Blend ? m.alpha : 1.0f;
    const glm::vec3 through = gpu::transmissionFilter(m.baseColor, m.metallic, m.transmission, m.ior, 1.0f);
    return gpu::scalarOpacityForm(gpu::surfaceOpticsOf(glm::vec3(0.0f), coverage, through)).a;
}
// The base colour texture, COLOR_0 and MASK of object `index` for point_samples.comp.glsl.
void setDetailUniforms(GLuint p, const GpuScene& scene, int index) {
    const GpuMesh& mesh = scene.meshOf(index);
    const BaseColorDetail d = scene.baseColorDetail(index);
    if (d.textured) {
        glProgramUniformMatrix3fv(p, glGetUniformLocation(p, "uBaseColorTransform"), 1, GL_FALSE,
                                  glm::value_ptr(d.transform));
        scene.bindMaterialTextures(index);
    }
    glProgramUniform1i(p, glGetUniformLocation(p, "uTextured"), d.textured);
    glProgramUniform1i(p, glGetUniformLocation(p, "uTexCoordOffset"),
                       d.textured ? GLint(mesh.texCoordOffset[d.texCoord] / sizeof(float)) : -1);
    glProgramUniform1i(p, glGetUniformLocation(p, "uColorOffset"),
                       d.vertexColor ? GLint(mesh.colorOffset / sizeof(float)) : -1);
    glProgramUniform1f(p, glGetUniformLocation(p, "uFactorAlpha"), d.factorAlpha);
    glProgramUniform1f(p, glGetUniformLocation(p, "uAlphaCutoff"), d.alphaCutoff);
    if (d.textured || d.vertexColor)
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BIND_MESH_ATTRIBUTES, mesh.attributes.id());
}
}  // namespace

std::uint64_t PointSamples::run(const FrameContext& frame, const PassParameters& parameters, double maxTriangleSamples,
                                std::uint64_t& trianglesBounded) {
    const GLuint p = sampleProgram_.id();
    const GLuint zero[2] = {0, 0};
    glNamedBufferSubData(counters_.id(), 0, sizeof(zero), zero);
    glBindBufferBase(GL_ATOMIC_COUNTER_BUFFER, gpu::BIND_COUNTERS, counters_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BIND_POINTS, points_.id());
    setSamplingUniforms(p, frame, parameters);
    glProgramUniform1ui(p, glGetUniformLocation(p, "uCapacity"), GLuint(std::min<std::uint64_t>(capacity_, 0xffffffffu)));
    glProgramUniform1f(p, glGetUniformLocation(p, "uMaxTriangleSamples"), float(maxTriangleSamples));
    // Enough chunks for a bounding box twice the largest lattice (a right triangle's box).
    const GLuint chunks = GLuint(std::ceil(2.0 * maxTriangleSamples / gpu::POINT_CHUNK)) + 1;
    glProgramUniform1ui(p, glGetUniformLocation(p, "uChunks"), chunks);
    glUseProgram(p);
    const auto& objects = frame.scene.objects();
    for (int index : frame.transparentOrder) {
        const Object& o = objects[index];
        const Material& m = frame.scene.scene().materials[o.material];
        const GpuMesh& mesh = frame.scene.meshOf(index);
        const GLuint triangles = GLuint(mesh.indexCount / 3);
        if (triangles == 0) continue;
        const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(o.world)));
        glProgramUniformMatrix4fv(p, glGetUniformLocation(p, "uModel"), 1, GL_FALSE, glm::value_ptr(o.world));
        glProgramUniformMatrix3fv(p, glGetUniformLocation(p, "uNormalMatrix"), 1, GL_FALSE, glm::value_ptr(normalMatrix));
        glProgramUniform1ui(p, glGetUniformLocation(p, "uTriangleCount"), triangles);
        glProgramUniform1ui(p, glGetUniformLocation(p, "uObjectId"), GLuint(o.id));
        glProgramUniform1f(p, glGetUniformLocation(p, "uAlpha"), keepProbability(m));
        setDetailUniforms(p, frame.scene, index);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BIND_MESH_VERTICES, mesh.vertices.id());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BIND_MESH_INDICES, mesh.indices.id());
        glDispatchCompute((triangles + gpu::POINT_SAMPLES_GROUP_SIZE - 1) / gpu::POINT_SAMPLES_GROUP_SIZE, chunks, 1);
    }
    glMemoryBarrier(GL_ATOMIC_COUNTER_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    GLuint counts[2] = {0, 0};
    glGetNamedBufferSubData(counters_.id(), 0, sizeof(counts), counts);
    trianglesBounded = counts[1];
    return counts[0];
}

PointSampling PointSamples::sample(const FrameContext& frame, const PassParameters& parameters, std::uint64_t maxPoints,
                                   double maxTriangleSamples) {
    if (!sampleProgram_) {
        sampleProgram_ = gl::buildProgram({"oit/screendoor/point_samples.comp.glsl"});
        counters_ = gl::Buffer::create();
        glNamedBufferStorage(counters_.id(), 2 * sizeof(GLuint), nullptr, GL_DYNAMIC_STORAGE_BIT);
        colors_ = gl::Buffer::create();
    }
    // The points shade under the scene's lights: the light loop only where it has its own.
    const bool punctual = !frame.scene.scene().lights.empty();
    if (!drawProgram_ || drawProgramPunctual_ != punctual) {
        gl::Defines defines;
        if (punctual) defines["STRATA_PUNCTUAL_LIGHTS"] = "";
        drawProgram_ = gl::buildProgram({"oit/screendoor/points.vert.glsl", "oit/screendoor/points.frag.glsl"}, defines);
        drawProgramPunctual_ = punctual;
    }
    // Colours by object id, for the point pass.
    const auto& objects = frame.scene.objects();
    std::vector<glm::vec4> colors(std::max<std::size_t>(objects.size(), 1), glm::vec4(0.0f));
    // Alpha 0 marks an unlit material (shaders/oit/screendoor/points.frag.glsl).
    for (const Object& o : objects) {
        const Material& m = frame.scene.scene().materials[o.material];
        // Glass scatters only what it does not transmit (shading_model.h's diffuseAlbedo).
        const float diffuse = m.transmissive() ? 1.0f - m.transmission : 1.0f;
        colors[std::size_t(o.id)] = glm::vec4(m.baseColor * diffuse, m.unlit ? 0.0f : 1.0f);
    }
    gl::allocateBuffer(colors_, colors.size() * sizeof(glm::vec4), GL_DYNAMIC_DRAW, "screendoor-object-sw colours");
    glNamedBufferSubData(colors_.id(), 0, GLsizeiptr(colors.size() * sizeof(glm::vec4)), colors.data());

    PointSampling result;
    if (capacity_ == 0) {
        capacity_ = std::min<std::uint64_t>(kInitialPoints, maxPoints);
        gl::allocateBuffer(points_, capacity_ * sizeof(gpu::ScreenDoorPoint), GL_DYNAMIC_COPY, "screendoor-object-sw points");
    }
    result.pointsWanted = run(frame, parameters, maxTriangleSamples, result.trianglesBounded);
    // Grow to what the lattices wanted (up to the bound) and sample again: same seed, same points.
    if (result.pointsWanted > capacity_ && capacity_ < maxPoints) {
        capacity_ = std::min<std::uint64_t>(maxPoints, std::bit_ceil(result.pointsWanted));
        gl::allocateBuffer(points_, capacity_ * sizeof(gpu::ScreenDoorPoint), GL_DYNAMIC_COPY, "screendoor-object-sw points");
        result.pointsWanted = run(frame, parameters, maxTriangleSamples, result.trianglesBounded);
        result.regrows = 1;
    }
    stored_ = result.pointsStored = std::min(result.pointsWanted, capacity_);
    return result;
}

void PointSamples::draw(const FrameContext& tileFrame) const {
    const GLuint p = drawProgram_.id();
    glProgramUniformMatrix4fv(p, glGetUniformLocation(p, "uViewProj"), 1, GL_FALSE, glm::value_ptr(tileFrame.viewProjection));
    tileFrame.scene.setViewLightUniforms(p, glGetUniformLocation(p, "uLightDir"), glGetUniformLocation(p, "uEye"),
                                         tileFrame.viewProjection);
    tileFrame.scene.setLightUniforms(p, glGetUniformLocation(p, "uLightCount"));
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BIND_POINTS, points_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BIND_OBJECT_COLORS, colors_.id());
    glUseProgram(p);
    glBindVertexArray(tileFrame.targets.emptyVertexArray());
    glDisable(GL_PROGRAM_POINT_SIZE);
    glPointSize(1.0f);  // one supersampled pixel (4.1.1)
    if (stored_ > 0) glDrawArrays(GL_POINTS, 0, GLsizei(stored_));
}

std::uint64_t PointSamples::bytes() const {
    return capacity_ * sizeof(gpu::ScreenDoorPoint) + 2 * sizeof(GLuint);
}

}  // namespace strata::screendoor
