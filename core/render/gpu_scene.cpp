#include "render/gpu_scene.hpp"

#include "common/bindings.h"

#include <glm/gtc/type_ptr.hpp>

#include <stdexcept>

namespace strata {

GpuMesh uploadMesh(const Mesh& mesh) {
    if (mesh.normals.size() != mesh.positions.size())
        throw std::runtime_error("mesh '" + mesh.name + "' has " + std::to_string(mesh.normals.size()) +
                                 " normals for " + std::to_string(mesh.positions.size()) + " positions");
    std::vector<float> interleaved;
    interleaved.reserve(mesh.positions.size() * 6);
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        const auto& p = mesh.positions[i];
        const auto& n = mesh.normals[i];
        interleaved.insert(interleaved.end(), {p.x, p.y, p.z, n.x, n.y, n.z});
    }
    GpuMesh g;
    g.vertexArray = gl::VertexArray::create();
    g.vertices = gl::Buffer::create();
    g.indices = gl::Buffer::create();
    glNamedBufferStorage(g.vertices.id(), GLsizeiptr(std::max<std::size_t>(interleaved.size(), 1) * sizeof(float)),
                         interleaved.empty() ? nullptr : interleaved.data(), 0);
    glNamedBufferStorage(g.indices.id(), GLsizeiptr(std::max<std::size_t>(mesh.indices.size(), 1) * 4),
                         mesh.indices.empty() ? nullptr : mesh.indices.data(), 0);
    GLuint vao = g.vertexArray.id();
    glVertexArrayVertexBuffer(vao, 0, g.vertices.id(), 0, 6 * sizeof(float));
    glVertexArrayElementBuffer(vao, g.indices.id());
    glEnableVertexArrayAttrib(vao, 0);
    glEnableVertexArrayAttrib(vao, 1);
    glVertexArrayAttribFormat(vao, 0, 3, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribFormat(vao, 1, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float));
    glVertexArrayAttribBinding(vao, 0, 0);
    glVertexArrayAttribBinding(vao, 1, 0);
    g.indexCount = GLsizei(mesh.indices.size());
    return g;
}

GpuScene::GpuScene(Scene scene) : scene_(std::move(scene)), objects_(flatten(scene_)) {
    meshes_.reserve(scene_.meshes.size());
    for (const Mesh& mesh : scene_.meshes) meshes_.push_back(uploadMesh(mesh));
    volumes_ = classifyVolumes(scene_, objects_);
    for (std::size_t i = 0; i < objects_.size(); ++i) {
        const ObjectVolume& v = volumes_[i];
        // gl_FrontFacing is the winding on screen: a world with a negative determinant mirrors it.
        const bool mirrored = glm::determinant(glm::mat3(objects_[i].world)) < 0.0f;
        volumeEntry_.push_back(!v.volume ? 0 : (v.entersThroughFront != mirrored ? 1 : -1));
    }
    for (const Mesh& mesh : scene_.meshes)
        // The volumetric stores put two flags above the primitive id (volume_bindings.h).
        if (mesh.triangleCount() >= (std::size_t(1) << 30))
            throw std::runtime_error("mesh '" + mesh.name + "' has 2^30 triangles or more");
    for (const Object& o : objects_) {
        bounds_.extend(o.worldBounds);
        triangles_ += scene_.meshes[o.mesh].triangleCount();
        (scene_.materials[o.material].isTransparent() ? transparent_ : opaque_).push_back(o.id);
    }
}

void GpuScene::setFrameUniforms(const SceneProgram& p, const glm::mat4& viewProjection) const {
    glProgramUniformMatrix4fv(p.id(), p.viewProj, 1, GL_FALSE, glm::value_ptr(viewProjection));
    glProgramUniform3fv(p.id(), p.lightDir, 1, glm::value_ptr(scene_.lightDirection));
}

void GpuScene::setObjectUniforms(const SceneProgram& p, int objectIndex) const {
    const Object& o = objects_[objectIndex];
    const Material& m = scene_.materials[o.material];
    glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(o.world)));
    GLuint program = p.id();
    glProgramUniformMatrix4fv(program, p.model, 1, GL_FALSE, glm::value_ptr(o.world));
    glProgramUniformMatrix3fv(program, p.normalMatrix, 1, GL_FALSE, glm::value_ptr(normalMatrix));
    glProgramUniform3fv(program, p.baseColor, 1, glm::value_ptr(m.baseColor));
    glProgramUniform1f(program, p.alpha, m.alpha);
    glProgramUniform1ui(program, p.objectId, GLuint(o.id));
    glProgramUniform1f(program, p.alphaCutoff, m.alphaMode == AlphaMode::Mask ? m.alphaCutoff : 0.0f);
    glProgramUniform3fv(program, p.tau, 1, glm::value_ptr(m.tau));
    glProgramUniform3fv(program, p.albedo, 1, glm::value_ptr(m.albedo));
    glProgramUniform1i(program, p.volumeEntry, volumeEntry_[std::size_t(objectIndex)]);
}

void GpuScene::draw(const SceneProgram& p, int objectIndex, const StandInDraw* standIn) const {
    if (standIn) {
        drawStandIn(p, objectIndex, *standIn);
        return;
    }
    setObjectUniforms(p, objectIndex);
    const GpuMesh& mesh = meshes_[objects_[objectIndex].mesh];
    if (mesh.indexCount == 0) return;
    glBindVertexArray(mesh.vertexArray.id());
    glDrawElements(GL_TRIANGLES, mesh.indexCount, GL_UNSIGNED_INT, nullptr);
}

void GpuScene::drawStandIn(const SceneProgram& p, int objectIndex, const StandInDraw& standIn) const {
    if (standIn.first.empty()) return;
    // The pass's program, built with the impostor alpha test, its uniforms as the pass set them.
    const SceneProgram& variant = p.standInVariant();
    setObjectUniforms(variant, objectIndex);
    glProgramUniform1i(variant.id(), variant.impostorSlices, standIn.slices);
    glProgramUniform1f(variant.id(), variant.impostorOverlap, standIn.overlap);
    glBindTextureUnit(gpu::BIND_IMPOSTOR_ATLAS, standIn.atlas);
    glUseProgram(variant.id());
    glBindVertexArray(standIn.vertexArray);
    glMultiDrawArrays(GL_TRIANGLES, standIn.first.data(), standIn.count.data(), GLsizei(standIn.first.size()));
    glUseProgram(p.id());  // the pass goes on with its own program bound
}

}  // namespace strata
