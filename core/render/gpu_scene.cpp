#include "render/gpu_scene.hpp"

#include "common/bindings.h"
#include "scene/texture_sampling.hpp"

#include <glm/gtc/type_ptr.hpp>

#include <cstring>
#include <stdexcept>

namespace strata {
namespace {

// Appends `values` to `bytes` as attribute `location` of `vao` (its own binding point),
// `components` floats per vertex.
template <class T>
void addAttribute(std::vector<unsigned char>& bytes, const std::vector<T>& values, GLuint vao, GLuint location,
                  int components, std::vector<std::pair<GLuint, std::size_t>>& bindings) {
    const std::size_t offset = bytes.size();
    bytes.resize(offset + values.size() * sizeof(T));
    std::memcpy(bytes.data() + offset, values.data(), values.size() * sizeof(T));
    glEnableVertexArrayAttrib(vao, location);
    glVertexArrayAttribFormat(vao, location, components, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(vao, location, location);
    bindings.push_back({location, offset});
}

}  // namespace

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

    // The material attributes, only those the mesh has.
    std::vector<unsigned char> bytes;
    std::vector<std::pair<GLuint, std::size_t>> bindings;  // location, byte offset
    const GLuint texCoordLocation[2] = {gpu::ATTRIB_TEXCOORD0, gpu::ATTRIB_TEXCOORD1};
    for (int set = 0; set < 2; ++set) {
        if (!mesh.hasTexCoords(set)) continue;
        if (mesh.texCoords[set].size() != mesh.positions.size())
            throw std::runtime_error("mesh '" + mesh.name + "' has " + std::to_string(mesh.texCoords[set].size()) +
                                     " TEXCOORD_" + std::to_string(set) + " for " +
                                     std::to_string(mesh.positions.size()) + " positions");
        addAttribute(bytes, mesh.texCoords[set], vao, texCoordLocation[set], 2, bindings);
        g.texCoords[set] = true;
    }
    if (mesh.hasColors()) {
        if (mesh.colors.size() != mesh.positions.size())
            throw std::runtime_error("mesh '" + mesh.name + "' has " + std::to_string(mesh.colors.size()) +
                                     " colours for " + std::to_string(mesh.positions.size()) + " positions");
        addAttribute(bytes, mesh.colors, vao, gpu::ATTRIB_COLOR, 4, bindings);
        g.colors = true;
    }
    if (!bytes.empty()) {
        g.attributes = gl::Buffer::create();
        glNamedBufferStorage(g.attributes.id(), GLsizeiptr(bytes.size()), bytes.data(), 0);
        for (const auto& [location, offset] : bindings) {
            const GLsizei stride = location == gpu::ATTRIB_COLOR ? 4 * sizeof(float) : 2 * sizeof(float);
            glVertexArrayVertexBuffer(vao, location, g.attributes.id(), GLintptr(offset), stride);
        }
    }
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
    uploadTextures();
    for (const Object& o : objects_) {
        const Material& m = scene_.materials[std::size_t(o.material)];
        const Mesh& mesh = scene_.meshes[std::size_t(o.mesh)];
        unsigned f = 0;
        if (usesBaseColorTexture(scene_, m, mesh)) f |= kSceneBaseColorTexture;
        if (mesh.hasColors()) f |= kSceneVertexColor;
        if (m.alphaTested()) f |= kSceneAlphaMask;
        features_.push_back(f);
    }
}

void GpuScene::uploadTextures() {
    for (const TextureImage& image : scene_.images) {
        if (image.width <= 0 || image.height <= 0 ||
            image.rgba.size() != std::size_t(image.width) * std::size_t(image.height) * 4)
            throw std::runtime_error("texture image '" + image.name + "' has " + std::to_string(image.rgba.size()) +
                                     " bytes for " + std::to_string(image.width) + "x" +
                                     std::to_string(image.height) + " RGBA8");
        int levels = 1;
        for (int side = std::max(image.width, image.height); side > 1; side /= 2) ++levels;
        gl::Texture t = gl::createTexture(GL_TEXTURE_2D);
        // sRGB storage: the sampler decodes texels to linear before filtering (glTF 3.9.2).
        glTextureStorage2D(t.id(), levels, GL_SRGB8_ALPHA8, image.width, image.height);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTextureSubImage2D(t.id(), 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glGenerateTextureMipmap(t.id());
        // Each level a quarter of the one above: 4/3 of level 0 in all.
        textureBytes_ += image.rgba.size() * 4 / 3;
        textures_.push_back(std::move(t));
    }
    for (const Material& m : scene_.materials) {
        if (!m.baseColorTexture.present()) {
            materialSampler_.push_back(-1);
            continue;
        }
        const Sampler& key = m.baseColorTexture.sampler;
        int index = -1;
        for (std::size_t i = 0; i < samplers_.size(); ++i)
            if (samplers_[i].first == key) index = int(i);
        if (index < 0) {
            gl::Sampler object = gl::Sampler::create();
            glSamplerParameteri(object.id(), GL_TEXTURE_MAG_FILTER, GLint(key.magFilter));
            glSamplerParameteri(object.id(), GL_TEXTURE_MIN_FILTER, GLint(key.minFilter));
            glSamplerParameteri(object.id(), GL_TEXTURE_WRAP_S, GLint(key.wrapS));
            glSamplerParameteri(object.id(), GL_TEXTURE_WRAP_T, GLint(key.wrapT));
            samplers_.push_back({key, std::move(object)});
            index = int(samplers_.size()) - 1;
        }
        materialSampler_.push_back(index);
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
    if (p.baseColorTransform >= 0) {
        const glm::mat3 transform = m.baseColorTexture.transform.matrix();
        glProgramUniformMatrix3fv(program, p.baseColorTransform, 1, GL_FALSE, glm::value_ptr(transform));
        glProgramUniform1i(program, p.baseColorTexCoord, m.baseColorTexture.texCoord);
    }
}

void GpuScene::bindMaterialTextures(int objectIndex) const {
    const Object& o = objects_[std::size_t(objectIndex)];
    const Material& m = scene_.materials[std::size_t(o.material)];
    glBindTextureUnit(gpu::BIND_BASE_COLOR_TEXTURE, textures_[std::size_t(m.baseColorTexture.image)].id());
    glBindSampler(gpu::BIND_BASE_COLOR_TEXTURE,
                  samplers_[std::size_t(materialSampler_[std::size_t(o.material)])].second.id());
}

void GpuScene::draw(const SceneProgram& p, int objectIndex, const StandInDraw* standIn) const {
    if (standIn) {
        drawStandIn(p, objectIndex, *standIn);
        return;
    }
    const GpuMesh& mesh = meshes_[objects_[objectIndex].mesh];
    if (mesh.indexCount == 0) return;
    // A material that needs more than its factors draws with the pass's program built for it,
    // the pass's uniforms copied over; a factor-only one with the pass's own program.
    const unsigned features = features_[std::size_t(objectIndex)];
    const SceneProgram& drawing = p.variant(features);
    setObjectUniforms(drawing, objectIndex);
    if (features & kSceneBaseColorTexture) bindMaterialTextures(objectIndex);
    if (features) glUseProgram(drawing.id());
    glBindVertexArray(mesh.vertexArray.id());
    glDrawElements(GL_TRIANGLES, mesh.indexCount, GL_UNSIGNED_INT, nullptr);
    if (features) glUseProgram(p.id());  // the pass goes on with its own program bound
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
