#include "render/gpu_scene.hpp"


#include "common/bindings.h"
#include "gl/debug.hpp"
#include "scene/lights.hpp"
#include "scene/texture_sampling.hpp"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>

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

// An attribute must have one value per position.
void checkCount(const Mesh& mesh, std::size_t count, const char* what) {
    if (count != mesh.positions.size())
        throw std::runtime_error("mesh '" + mesh.name + "' has " + std::to_string(count) + " " + what + " for " +
                                 std::to_string(mesh.positions.size()) + " positions");
}

// Which encoding, texture unit and build feature each MaterialSlot has.
struct SlotInfo {
    bool srgb;
    GLuint unit;
    unsigned feature;
};
constexpr SlotInfo kSlots[kMaterialSlots] = {
    {true, gpu::BIND_BASE_COLOR_TEXTURE, kSceneBaseColorTexture},
    {false, gpu::BIND_METALLIC_ROUGHNESS_TEXTURE, kSceneMetallicRoughnessTexture},
    {false, gpu::BIND_NORMAL_TEXTURE, kSceneNormalTexture},
    {false, gpu::BIND_OCCLUSION_TEXTURE, kSceneOcclusionTexture},
    {true, gpu::BIND_EMISSIVE_TEXTURE, kSceneEmissiveTexture},
};

// An image as a mipmapped texture: sRGB storage decodes texels to linear before filtering
// (glTF 3.9.2); linear storage leaves them as they are.
gl::Texture uploadImage(const TextureImage& image, bool srgb) {
    int levels = 1;
    for (int side = std::max(image.width, image.height); side > 1; side /= 2) ++levels;
    gl::Texture t = gl::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(t.id(), levels, srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8, image.width, image.height);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTextureSubImage2D(t.id(), 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glGenerateTextureMipmap(t.id());
    return t;
}

// STRATA_DEBUG_FINISH_DRAWS=1: glFinish after every object's draw. A diagnostic for a GPU that
// loses objects now and then (docs/gpu-h100.md, group 2): if the loss goes, it is a hazard
// between draws; it costs a stall per object.
void finishIfDebugging() {
    static const bool finish = gl::debugSwitch("STRATA_DEBUG_FINISH_DRAWS");
    if (finish) glFinish();
}

// common/lighting.glsl's uEye for a view-projection: (eye, 1) for a perspective camera,
// (direction towards the eye, 0) for an orthographic one.
glm::vec4 eyeUniform(const glm::mat4& viewProjection) {
    // The preimage of (0, 0, 1, 0) under the view-projection: the point every clip-space ray
    // leaves from. For a perspective camera its w is non-zero and the point finite; for an
    // orthographic one it is the direction away from the scene, which the shader takes as
    // constant.
    const glm::dvec4 eye = glm::inverse(glm::dmat4(viewProjection)) * glm::dvec4(0.0, 0.0, 1.0, 0.0);
    const glm::dvec3 xyz(eye);
    if (std::abs(eye.w) > 1e-12 * glm::length(xyz)) return glm::vec4(glm::vec3(xyz / eye.w), 1.0f);
    if (glm::length(xyz) > 0.0) return glm::vec4(glm::vec3(-glm::normalize(xyz)), 0.0f);
    return glm::vec4(0.0f, 0.0f, 1.0f, 0.0f);
}

}  // namespace

const TextureRef& materialTexture(const Material& m, int slot) {
    switch (slot) {
    case kSlotMetallicRoughness: return m.metallicRoughnessTexture;
    case kSlotNormal: return m.normalTexture;
    case kSlotOcclusion: return m.occlusionTexture;
    case kSlotEmissive: return m.emissiveTexture;
    case kSlotBaseColor:
    default: return m.baseColorTexture;
    }
}

GpuMesh uploadMesh(const Mesh& mesh) {
    checkCount(mesh, mesh.normals.size(), "normals");
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
        checkCount(mesh, mesh.texCoords[set].size(), ("TEXCOORD_" + std::to_string(set)).c_str());
        addAttribute(bytes, mesh.texCoords[set], vao, texCoordLocation[set], 2, bindings);
        g.texCoords[set] = true;
        g.texCoordOffset[set] = bindings.back().second;
    }
    if (mesh.hasColors()) {
        checkCount(mesh, mesh.colors.size(), "colours");
        addAttribute(bytes, mesh.colors, vao, gpu::ATTRIB_COLOR, 4, bindings);
        g.colors = true;
        g.colorOffset = bindings.back().second;
    }
    if (mesh.hasTangents()) {
        checkCount(mesh, mesh.tangents.size(), "tangents");
        addAttribute(bytes, mesh.tangents, vao, gpu::ATTRIB_TANGENT, 4, bindings);
        g.tangents = true;
    }
    if (!bytes.empty()) {
        g.attributes = gl::Buffer::create();
        glNamedBufferStorage(g.attributes.id(), GLsizeiptr(bytes.size()), bytes.data(), 0);
        for (const auto& [location, offset] : bindings) {
            const bool vec4 = location == gpu::ATTRIB_COLOR || location == gpu::ATTRIB_TANGENT;
            const GLsizei stride = vec4 ? 4 * sizeof(float) : 2 * sizeof(float);
            glVertexArrayVertexBuffer(vao, location, g.attributes.id(), GLintptr(offset), stride);
        }
    }
    return g;
}

GpuScene::GpuScene(Scene scene) : scene_(std::move(scene)), objects_(flatten(scene_)), cullHierarchy_(objects_) {
    meshes_.reserve(scene_.meshes.size());
    for (const Mesh& mesh : scene_.meshes) {
        meshes_.push_back(uploadMesh(mesh));
        meshTriangles_ += mesh.triangleCount();
        // As uploadMesh lays them out: 24-byte vertices, 4-byte indices, the material attributes.
        meshBytes_ += mesh.positions.size() * 24 + mesh.indices.size() * 4 +
                      mesh.positions.size() * (8 * (mesh.hasTexCoords(0) + mesh.hasTexCoords(1)) +
                                               16 * (mesh.hasColors() + mesh.hasTangents()));
    }
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
    std::vector<gpu::PunctualLight> lights = placeLights(scene_);
    lightCount_ = int(lights.size());
    lights.resize(std::size_t(gpu::kMaxLights));  // the block's declared size
    lights_ = gl::Buffer::create();
    glNamedBufferStorage(lights_.id(), GLsizeiptr(lights.size() * sizeof(gpu::PunctualLight)), lights.data(), 0);
    for (const Object& o : objects_) {
        const Material& m = scene_.materials[std::size_t(o.material)];
        const Mesh& mesh = scene_.meshes[std::size_t(o.mesh)];
        unsigned f = 0;
        for (int slot = 0; slot < kMaterialSlots; ++slot)
            if (slot == kSlotNormal ? usesNormalTexture(scene_, m, mesh) : usesTexture(scene_, materialTexture(m, slot), mesh))
                f |= kSlots[slot].feature;
        if (mesh.hasColors()) f |= kSceneVertexColor;
        if (m.alphaTested()) f |= kSceneAlphaMask;
        if (m.unlit) f = (f & (kSceneBaseColorTexture | kSceneVertexColor | kSceneAlphaMask)) | kSceneUnlit;
        // A scene with its own lights shades through the light loop; one without, through the
        // default rig's single directional light, with no loop and no light block to read.
        else if (!scene_.lights.empty()) f |= kScenePunctualLights;
        if (m.usesTransmissionModel()) f |= kSceneTransmission;
        // Only a transparent object's filter reaches a technique's storage.
        if (m.transmissive()) coloredFilters_ = true;
        features_.push_back(f);
        volumeFilter_.push_back(volumeFilterOnEntry(m, o.world));
    }
    records_.reserve(objects_.size());
    for (std::size_t i = 0; i < objects_.size(); ++i)
        records_.push_back(makeObjectRecord(objects_[i].world, unsigned(objects_[i].id), volumeEntry_[i], volumeFilter_[i]));

    // Batched orders: stable by (mesh, material), so each batch's objects keep their object order.
    auto batchKey = [&](int o) {
        const Object& object = objects_[std::size_t(o)];
        return std::pair(object.mesh, object.material);
    };
    for (auto [from, to] : {std::pair{&opaque_, &opaqueBatched_}, std::pair{&transparent_, &transparentBatched_}}) {
        *to = *from;
        std::stable_sort(to->begin(), to->end(), [&](int a, int b) { return batchKey(a) < batchKey(b); });
    }

    // The record buffer: the objects' own records, then the ring. A run is at most every object,
    // so the ring holds two of the longest and a pass's runs rarely wrap.
    streamRing_ = std::max<std::size_t>(2 * objects_.size(), 1024);
    std::vector<gpu::ObjectRecord> initial = records_;
    initial.resize(records_.size() + streamRing_);
    recordBuffer_ = gl::Buffer::create();
    glNamedBufferStorage(recordBuffer_.id(), GLsizeiptr(initial.size() * sizeof(gpu::ObjectRecord)), initial.data(),
                         GL_DYNAMIC_STORAGE_BIT);
    for (GpuMesh& mesh : meshes_) attachObjectRecords(mesh.vertexArray.id(), recordBuffer_.id());
}

void GpuScene::uploadTextures() {
    // Which encodings each image is used in.
    std::vector<std::array<bool, 2>> used(scene_.images.size(), {false, false});  // sRGB, linear
    for (const Material& m : scene_.materials)
        for (int slot = 0; slot < kMaterialSlots; ++slot) {
            const TextureRef& t = materialTexture(m, slot);
            if (t.present() && std::size_t(t.image) < used.size()) used[std::size_t(t.image)][kSlots[slot].srgb ? 0 : 1] = true;
        }
    srgbTextures_.resize(scene_.images.size());
    linearTextures_.resize(scene_.images.size());
    for (std::size_t i = 0; i < scene_.images.size(); ++i) {
        const TextureImage& image = scene_.images[i];
        if (image.width <= 0 || image.height <= 0 ||
            image.rgba.size() != std::size_t(image.width) * std::size_t(image.height) * 4)
            throw std::runtime_error("texture image '" + image.name + "' has " + std::to_string(image.rgba.size()) +
                                     " bytes for " + std::to_string(image.width) + "x" +
                                     std::to_string(image.height) + " RGBA8");
        // Each level a quarter of the one above: 4/3 of level 0 in all.
        if (used[i][0]) {
            srgbTextures_[i] = uploadImage(image, true);
            textureBytes_ += image.rgba.size() * 4 / 3;
        }
        if (used[i][1]) {
            linearTextures_[i] = uploadImage(image, false);
            textureBytes_ += image.rgba.size() * 4 / 3;
        }
    }
    for (const Material& m : scene_.materials) {
        std::array<int, kMaterialSlots> indices;
        for (int slot = 0; slot < kMaterialSlots; ++slot) {
            const TextureRef& t = materialTexture(m, slot);
            indices[std::size_t(slot)] = -1;
            if (!t.present()) continue;
            const Sampler& key = t.sampler;
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
            indices[std::size_t(slot)] = index;
        }
        materialSampler_.push_back(indices);
    }
}

namespace {

// STRATA_DEBUG_CHECK_UNIFORMS=1: reads back what was just set (docs/gpu-h100.md, group 2).
bool checkingUniforms() {
    static const bool on = gl::debugSwitch("STRATA_DEBUG_CHECK_UNIFORMS");
    return on;
}

// STRATA_DEBUG_FRAME_UNIFORMS_PER_DRAW=1: the frame's uniforms set again on the drawing program
// before every draw, rather than once per pass and copied onto variants.
bool frameUniformsPerDraw() {
    static const bool on = gl::debugSwitch("STRATA_DEBUG_FRAME_UNIFORMS_PER_DRAW");
    return on;
}

void checkUniform(GLuint program, GLint location, const float* want, int count, const char* what, int object) {
    if (location < 0) return;
    float got[16] = {}, set[16] = {};
    glGetUniformfv(program, location, got);
    std::memcpy(set, want, std::size_t(count) * sizeof(float));
    if (std::memcmp(got, set, std::size_t(count) * sizeof(float)) == 0) return;
    static int reported = 0;
    if (reported++ < 40)
        std::fprintf(stderr, "[strata debug] %s on program %u (object %d) reads back %g %g %g %g, set %g %g %g %g\n", what,
                     program, object, got[0], got[1], got[2], got[3], set[0], set[1], set[2], set[3]);
}

}  // namespace

void GpuScene::setFrameUniforms(const SceneProgram& p, const glm::mat4& viewProjection) const {
    p.uniformsChanged();  // a new pass: the technique may have set uniforms since the last
    glProgramUniformMatrix4fv(p.id(), p.viewProj, 1, GL_FALSE, glm::value_ptr(viewProjection));
    setViewLightUniforms(p.id(), p.lightDir, p.eye, viewProjection);
    debugViewProjection_ = viewProjection;
    if (checkingUniforms()) checkUniform(p.id(), p.viewProj, glm::value_ptr(viewProjection), 16, "uViewProj (pass)", -1);
}

void GpuScene::setViewLightUniforms(GLuint program, GLint lightDir, GLint eye,
                                    const glm::mat4& viewProjection) const {
    const glm::vec3 toLight = glm::normalize(scene_.lightDirection);  // as scene/lights.hpp's defaultLight
    glProgramUniform3fv(program, lightDir, 1, glm::value_ptr(toLight));
    const glm::vec4 eyePoint = eyeUniform(viewProjection);
    glProgramUniform4fv(program, eye, 1, glm::value_ptr(eyePoint));
}

void GpuScene::setLightUniforms(GLuint program, GLint countLocation) const {
    glProgramUniform1i(program, countLocation, lightCount_);
    glBindBufferBase(GL_UNIFORM_BUFFER, gpu::BIND_LIGHTS, lights_.id());
}

void GpuScene::setMaterialUniforms(const SceneProgram& p, int objectIndex) const {
    const Object& o = objects_[std::size_t(objectIndex)];
    const Material& m = scene_.materials[std::size_t(o.material)];
    const GLuint program = p.id();
    glProgramUniform3fv(program, p.baseColor, 1, glm::value_ptr(m.baseColor));
    glProgramUniform1f(program, p.alpha, m.alpha);
    glProgramUniform1f(program, p.alphaCutoff, m.alphaMode == AlphaMode::Mask ? m.alphaCutoff : 0.0f);
    glProgramUniform3fv(program, p.tau, 1, glm::value_ptr(m.tau));
    glProgramUniform3fv(program, p.albedo, 1, glm::value_ptr(m.albedo));
    // The light loop's count, on the variant that has it (the pass's plain program does not, so
    // SceneProgram::variant has no value of it to copy).
    if (p.lightCount >= 0) setLightUniforms(program, p.lightCount);
    glProgramUniform1f(program, p.metallic, m.metallic);
    glProgramUniform1f(program, p.roughness, m.roughness);
    glProgramUniform3fv(program, p.emissive, 1, glm::value_ptr(m.emissive));
    const unsigned features = features_[std::size_t(objectIndex)];
    if (features & kSceneNormalTexture) glProgramUniform1f(program, p.normalScale, m.normalScale);
    if (features & kSceneOcclusionTexture) glProgramUniform1f(program, p.occlusionStrength, m.occlusionStrength);
    if (features & kSceneTransmission) {
        glProgramUniform1f(program, p.transmission, m.transmission);
        glProgramUniform1f(program, p.ior, m.ior);
        glProgramUniform1i(program, p.alphaBlend, m.alphaMode == AlphaMode::Blend);
    }
    for (int slot = 0; slot < kMaterialSlots; ++slot) {
        if (!(features & kSlots[slot].feature)) continue;
        const TextureRef& t = materialTexture(m, slot);
        const glm::mat3 transform = t.transform.matrix();
        glProgramUniformMatrix3fv(program, p.textures[slot].transform, 1, GL_FALSE, glm::value_ptr(transform));
        glProgramUniform1i(program, p.textures[slot].texCoord, t.texCoord);
    }
}

BaseColorDetail GpuScene::baseColorDetail(int objectIndex) const {
    const Object& o = objects_[std::size_t(objectIndex)];
    const Material& m = scene_.materials[std::size_t(o.material)];
    const unsigned features = features_[std::size_t(objectIndex)];
    BaseColorDetail d;
    d.textured = (features & kSceneBaseColorTexture) != 0;
    if (d.textured) {
        const TextureRef& t = materialTexture(m, kSlotBaseColor);
        d.transform = t.transform.matrix();
        d.texCoord = t.texCoord;
    }
    d.vertexColor = (features & kSceneVertexColor) != 0 && meshes_[std::size_t(o.mesh)].colors;
    d.factorAlpha = m.alpha;
    d.alphaCutoff = m.alphaMode == AlphaMode::Mask ? m.alphaCutoff : 0.0f;
    return d;
}

void GpuScene::bindMaterialTextures(int objectIndex) const {
    const Object& o = objects_[std::size_t(objectIndex)];
    const Material& m = scene_.materials[std::size_t(o.material)];
    const unsigned features = features_[std::size_t(objectIndex)];
    for (int slot = 0; slot < kMaterialSlots; ++slot) {
        if (!(features & kSlots[slot].feature)) continue;
        const std::size_t image = std::size_t(materialTexture(m, slot).image);
        glBindTextureUnit(kSlots[slot].unit, (kSlots[slot].srgb ? srgbTextures_ : linearTextures_)[image].id());
        glBindSampler(kSlots[slot].unit,
                      samplers_[std::size_t(materialSampler_[std::size_t(o.material)][std::size_t(slot)])].second.id());
    }
}

const SceneProgram& GpuScene::prepareVariant(const SceneProgram& p, int objectIndex) const {
    // A material that needs more than its factors draws with the pass's program built for it,
    // the pass's uniforms copied over; a factor-only one with the pass's own program.
    const SceneProgram& drawing = p.variant(features_[std::size_t(objectIndex)]);
    setMaterialUniforms(drawing, objectIndex);
    if (frameUniformsPerDraw()) {
        glProgramUniformMatrix4fv(drawing.id(), drawing.viewProj, 1, GL_FALSE, glm::value_ptr(debugViewProjection_));
        setViewLightUniforms(drawing.id(), drawing.lightDir, drawing.eye, debugViewProjection_);
    }
    if (checkingUniforms()) {
        checkUniform(drawing.id(), drawing.viewProj, glm::value_ptr(debugViewProjection_), 16, "uViewProj", objectIndex);
        const glm::vec4 eye = eyeUniform(debugViewProjection_);
        checkUniform(drawing.id(), drawing.eye, glm::value_ptr(eye), 4, "uEye", objectIndex);
        // The material's too: a wrong colour, alpha or cut-off fits what group 2 showed better
        // than a wrong transform does.
        const Material& m = scene_.materials[std::size_t(objects_[std::size_t(objectIndex)].material)];
        checkUniform(drawing.id(), drawing.baseColor, glm::value_ptr(m.baseColor), 3, "uBaseColor", objectIndex);
        checkUniform(drawing.id(), drawing.alpha, &m.alpha, 1, "uAlpha", objectIndex);
        const float cutoff = m.alphaMode == AlphaMode::Mask ? m.alphaCutoff : 0.0f;
        checkUniform(drawing.id(), drawing.alphaCutoff, &cutoff, 1, "uAlphaCutoff", objectIndex);
        checkUniform(drawing.id(), drawing.metallic, &m.metallic, 1, "uMetallic", objectIndex);
        checkUniform(drawing.id(), drawing.roughness, &m.roughness, 1, "uRoughness", objectIndex);
        checkUniform(drawing.id(), drawing.emissive, glm::value_ptr(m.emissive), 3, "uEmissive", objectIndex);
        checkUniform(drawing.id(), drawing.tau, glm::value_ptr(m.tau), 3, "uTau", objectIndex);
        checkUniform(drawing.id(), drawing.albedo, glm::value_ptr(m.albedo), 3, "uAlbedo", objectIndex);
        const glm::vec3 toLight = glm::normalize(scene_.lightDirection);
        checkUniform(drawing.id(), drawing.lightDir, glm::value_ptr(toLight), 3, "uLightDir", objectIndex);
    }
    bindMaterialTextures(objectIndex);
    if (&drawing != &p) glUseProgram(drawing.id());
    return drawing;
}

bool GpuScene::sameBatch(int a, int b) const {
    // The material's uniforms, textures and program variant are set once per draw; the variant
    // follows from the mesh and the material.
    const Object &x = objects_[std::size_t(a)], &y = objects_[std::size_t(b)];
    return x.mesh == y.mesh && x.material == y.material;
}

void GpuScene::draw(const SceneProgram& p, int objectIndex, const StandInDraw* standIn) const {
    if (standIn) {
        drawStandIns(p, std::span<const int>(&objectIndex, 1), *standIn);
        return;
    }
    const GpuMesh& mesh = meshes_[objects_[std::size_t(objectIndex)].mesh];
    if (mesh.indexCount == 0) return;
    const SceneProgram& drawing = prepareVariant(p, objectIndex);
    glBindVertexArray(mesh.vertexArray.id());
    // One instance reading record `objectIndex`: the object's own.
    glDrawElementsInstancedBaseInstance(GL_TRIANGLES, mesh.indexCount, GL_UNSIGNED_INT, nullptr, 1,
                                        GLuint(objectIndex));
    ++drawCalls_;
    finishIfDebugging();
    if (&drawing != &p) glUseProgram(p.id());  // the pass goes on with its own program bound
}

std::size_t GpuScene::recordsOf(std::span<const int> objects) const {
    bool consecutive = true;
    for (std::size_t k = 1; k < objects.size() && consecutive; ++k) consecutive = objects[k] == objects[k - 1] + 1;
    if (consecutive) return std::size_t(objects[0]);
    // glNamedBufferSubData leaves draws already issued reading what they read, so a wrapped ring
    // is still right (the driver may stall).
    const std::size_t n = objects.size();
    runScratch_.clear();
    for (int o : objects) runScratch_.push_back(records_[std::size_t(o)]);
    if (streamHead_ + n > streamRing_) streamHead_ = 0;
    const std::size_t at = objects_.size() + streamHead_;
    glNamedBufferSubData(recordBuffer_.id(), GLintptr(at * sizeof(gpu::ObjectRecord)),
                         GLsizeiptr(n * sizeof(gpu::ObjectRecord)), runScratch_.data());
    streamHead_ += n;
    return at;
}

std::size_t GpuScene::drawObjects(const SceneProgram& p, const std::vector<int>& order,
                                  const StandIns* standIns) const {
    const std::uint64_t before = drawCalls_;
    auto standInOf = [&](int o) { return standIns ? (*standIns)[std::size_t(o)] : nullptr; };
    // STRATA_DEBUG_NO_BATCH=1: a draw per object, for telling a batching fault from another.
    static const bool noBatch = gl::debugSwitch("STRATA_DEBUG_NO_BATCH");
    std::size_t i = 0;
    while (i < order.size()) {
        const int first = order[i];
        std::size_t end = i + 1;
        if (const StandInDraw* s = standInOf(first)) {
            while (!noBatch && end < order.size() && standInOf(order[end]) &&
                   sameStandInBatch(first, *s, order[end], *standInOf(order[end])))
                ++end;
            drawStandIns(p, std::span<const int>(order).subspan(i, end - i), *s);
            i = end;
            continue;
        }
        while (!noBatch && end < order.size() && !standInOf(order[end]) && sameBatch(first, order[end])) ++end;
        const std::size_t n = end - i;
        if (n == 1) {
            draw(p, first);
            i = end;
            continue;
        }
        const GpuMesh& mesh = meshes_[objects_[std::size_t(first)].mesh];
        if (mesh.indexCount > 0) {
            const std::size_t at = recordsOf(std::span<const int>(order).subspan(i, n));
            const SceneProgram& drawing = prepareVariant(p, first);
            glBindVertexArray(mesh.vertexArray.id());
            glDrawElementsInstancedBaseInstance(GL_TRIANGLES, mesh.indexCount, GL_UNSIGNED_INT, nullptr, GLsizei(n),
                                                GLuint(at));
            ++drawCalls_;
            finishIfDebugging();
            if (&drawing != &p) glUseProgram(p.id());
        }
        i = end;
    }
    return std::size_t(drawCalls_ - before);
}

bool GpuScene::sameStandInBatch(int a, const StandInDraw& sa, int b, const StandInDraw& sb) const {
    const Object &x = objects_[std::size_t(a)], &y = objects_[std::size_t(b)];
    return x.material == y.material && features_[std::size_t(a)] == features_[std::size_t(b)] &&
           sameStandInDraw(sa, sb);
}

void GpuScene::drawStandIns(const SceneProgram& p, std::span<const int> objects, const StandInDraw& standIn) const {
    if (standIn.first.empty()) return;  // a LOD unit's part whose representative draws the unit
    const int objectIndex = objects[0];
    const std::size_t n = objects.size();
    // The pass's program, built with the impostor alpha test, its uniforms as the pass set them.
    const SceneProgram& variant =
        p.variant(kSceneStandIn | (features_[std::size_t(objectIndex)] & kSceneStandInKeeps));
    setMaterialUniforms(variant, objectIndex);
    // The quads read the records as instanced attributes, like a mesh (attached once per vertex
    // array: a new one, or one whose name was reused, reads no buffer yet).
    if (!readsObjectRecords(standIn.vertexArray, recordBuffer_.id()))
        attachObjectRecords(standIn.vertexArray, recordBuffer_.id());
    const std::size_t at = recordsOf(objects);
    // One command per slice range, each with the batch's instances.
    const std::size_t ranges = standIn.first.size();
    indirectScratch_.clear();
    for (std::size_t r = 0; r < ranges; ++r)
        indirectScratch_.insert(indirectScratch_.end(),
                                {GLuint(standIn.count[r]), GLuint(n), GLuint(standIn.first[r]), GLuint(at)});
    if (indirectHead_ + ranges > indirectCapacity_) {
        if (ranges > indirectCapacity_ / 2) {
            indirectCapacity_ = std::max<std::size_t>(1024, 4 * ranges);
            indirect_ = gl::Buffer::create();
            glNamedBufferStorage(indirect_.id(), GLsizeiptr(indirectCapacity_ * 4 * sizeof(GLuint)), nullptr,
                                 GL_DYNAMIC_STORAGE_BIT);
        }
        indirectHead_ = 0;
    }
    const std::size_t offset = indirectHead_ * 4 * sizeof(GLuint);
    glNamedBufferSubData(indirect_.id(), GLintptr(offset), GLsizeiptr(indirectScratch_.size() * sizeof(GLuint)),
                         indirectScratch_.data());
    indirectHead_ += ranges;
    glProgramUniform1i(variant.id(), variant.impostorSlices, standIn.slices);
    glProgramUniform1f(variant.id(), variant.impostorOverlap, standIn.overlap);
    glProgramUniform1i(variant.id(), variant.impostorAlbedo, standIn.albedo != 0);
    glBindTextureUnit(gpu::BIND_IMPOSTOR_ATLAS, standIn.atlas);
    if (standIn.albedo) glBindTextureUnit(gpu::BIND_IMPOSTOR_ALBEDO, standIn.albedo);
    glUseProgram(variant.id());
    glBindVertexArray(standIn.vertexArray);
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, indirect_.id());
    glMultiDrawArraysIndirect(GL_TRIANGLES, reinterpret_cast<const void*>(offset), GLsizei(ranges), 0);
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
    ++drawCalls_;
    finishIfDebugging();
    glUseProgram(p.id());  // the pass goes on with its own program bound
}

}  // namespace strata
