#pragma once
// The scene on the GPU: one vertex array per mesh, the flattened objects split into opaque and
// transparent lists, and the draw call every pass uses.
#include "gl/objects.hpp"
#include "render/scene_program.hpp"
#include "render/cull_hierarchy.hpp"
#include "render/object_records.hpp"
#include "render/stand_in.hpp"
#include "scene/mesh_volume.hpp"
#include "scene/scene.hpp"

#include <glm/glm.hpp>

#include <array>
#include <span>
#include <vector>

namespace strata {

struct GpuMesh {
    gl::VertexArray vertexArray;
    gl::Buffer vertices;    // interleaved position, normal (6 floats)
    gl::Buffer indices;     // uint32
    gl::Buffer attributes;  // what the mesh has of TEXCOORD_0, TEXCOORD_1, COLOR_0, TANGENT, one array each
    GLsizei indexCount = 0;
    bool texCoords[2] = {false, false};
    bool colors = false;
    // Where each array starts in `attributes`, in bytes (valid where the flag above is set).
    std::size_t texCoordOffset[2] = {0, 0};
    std::size_t colorOffset = 0;
    bool tangents = false;
};

// A material's textures, in the order of SceneProgram::textures and of their texture units.
enum MaterialSlot : int {
    kSlotBaseColor,
    kSlotMetallicRoughness,
    kSlotNormal,
    kSlotOcclusion,
    kSlotEmissive,
    kMaterialSlots,
};
const TextureRef& materialTexture(const Material& material, int slot);


// What a pass that reads an object's base colour outside GpuScene::draw needs (a compute pass,
// the impostor bake): which of the base colour texture and COLOR_0 apply, with the texture's
// KHR_texture_transform and TEXCOORD set, and the factor alpha and MASK cutoff (0: not MASK).
// GpuScene::bindMaterialTextures binds the texture.
struct BaseColorDetail {
    bool textured = false;
    glm::mat3 transform{1.0f};
    int texCoord = 0;
    bool vertexColor = false;
    float factorAlpha = 1.0f;
    float alphaCutoff = 0.0f;
};

// Uploads one mesh in the layout every scene program reads (attributes 0 position, 1 normal;
// ATTRIB_TEXCOORD0/1, ATTRIB_COLOR and ATTRIB_TANGENT of common/bindings.h where the mesh has them, in a buffer
// of their own so a mesh without them keeps its 24-byte vertices). Throws when an attribute
// does not match the positions.
GpuMesh uploadMesh(const Mesh& mesh);

class GpuScene {
public:
    explicit GpuScene(Scene scene);

    const Scene& scene() const { return scene_; }
    const std::vector<Object>& objects() const { return objects_; }
    const std::vector<int>& opaqueObjects() const { return opaque_; }
    const std::vector<int>& transparentObjects() const { return transparent_; }
    bool hasTransparency() const { return !transparent_.empty(); }
    // The same lists with the objects that can share an instanced draw (sameBatch) next to each
    // other, otherwise in object order: the order a pass whose result does not depend on the
    // submission order draws in (drawObjects then issues one draw per batch).
    const std::vector<int>& opaqueObjectsBatched() const { return opaqueBatched_; }
    const std::vector<int>& transparentObjectsBatched() const { return transparentBatched_; }
    const Bounds& bounds() const { return bounds_; }
    // The mesh an object draws, for passes that read its buffers directly (vertex pulling).
    const GpuMesh& meshOf(int objectIndex) const { return meshes_[objects_[objectIndex].mesh]; }
    std::size_t triangleCount() const { return triangles_; }  // drawn: over the objects
    // What the scene holds once however many objects draw it (a mesh placed N times is one):
    // its meshes, their triangles and their GPU buffers' bytes.
    std::size_t meshCount() const { return meshes_.size(); }
    std::size_t meshTriangleCount() const { return meshTriangles_; }
    std::size_t meshBytes() const { return meshBytes_; }
    // What the volumetric techniques make of each object (indexed like objects()): a medium, or
    // why it is drawn as a surface. Computed once at construction.
    const std::vector<ObjectVolume>& objectVolumes() const { return volumes_; }
    // The objects' bounding spheres in a hierarchy over the LOD units, for frustum culling.
    const CullHierarchy& cullHierarchy() const { return cullHierarchy_; }

    // Draws the object's triangles with `program`, which must be bound, or with `standIn` the
    // stand-in's quads in their place. The object's values (model, normal matrix, material with
    // its volume parameters tau and albedo, id, which faces enter a volume) are its records
    // (render/object_records.hpp), which this binds.
    void draw(const SceneProgram& program, int objectIndex, const StandInDraw* standIn = nullptr) const;
    // Draws `order` as draw() draws each, in that order, with one instanced draw for each run of
    // consecutive objects that share a mesh and a material: a field of one model is a draw per
    // part. Consecutive stand-ins that show the same slices of one impostor with one material
    // (sameStandInBatch) are one instanced draw too: a forest of one tree's impostor is a draw
    // per view direction in use. A run of consecutive object indices reads the objects' records
    // in place; another run's records are copied into a ring first. `standIns` as
    // FrameContext's (null: none). Returns the GL draws issued.
    std::size_t drawObjects(const SceneProgram& program, const std::vector<int>& order,
                            const StandIns* standIns = nullptr) const;
    // Whether two objects can share an instanced draw (drawObjects' runs).
    bool sameBatch(int a, int b) const;
    // Whether stand-ins `sa` of object a and `sb` of object b can: the same quads, atlas and
    // slice ranges (render/stand_in.hpp's sameStandInDraw), drawn with the same material.
    bool sameStandInBatch(int a, const StandInDraw& sa, int b, const StandInDraw& sb) const;
    // GL draw calls issued by draw() and drawObjects() since construction (the bench's and
    // panel's draw count is the difference over a frame).
    std::uint64_t drawCalls() const { return drawCalls_; }
    // The object records' bytes on the GPU (the objects' own and the ring).
    std::size_t recordBytes() const { return (records_.size() + streamRing_) * sizeof(gpu::ObjectRecord); }

    // Uniforms every scene program shares for a frame.
    void setFrameUniforms(const SceneProgram& program, const glm::mat4& viewProjection) const;
    // The default light's direction (uLightDir) and the eye (uEye) of common/lighting.glsl, for
    // a program that shades through it; setFrameUniforms sets them on scene programs.
    void setViewLightUniforms(GLuint program, GLint lightDir, GLint eye, const glm::mat4& viewProjection) const;
    // The scene's lights (scene/lights.hpp) for a program that shades through
    // common/lighting.glsl: binds their block and sets uLightCount at `countLocation`.
    void setLightUniforms(GLuint program, GLint countLocation) const;

    // The SceneFeature bits object `objectIndex` draws with (textures, vertex colours, MASK, unlit).
    unsigned materialFeatures(int objectIndex) const { return features_[std::size_t(objectIndex)]; }
    // Some transparent object filters what is behind it per channel (a transmissive material):
    // the techniques that composite RGB transmittance build their programs for it
    // (oit/color_model.hpp); every other scene keeps the scalar storage.
    bool hasColoredFilters() const { return coloredFilters_; }
    // Decoded texture images on the GPU, mip levels included (the panel's and bench's figure).
    std::size_t textureBytes() const { return textureBytes_; }
    // Binds the textures object `objectIndex` draws with, with their samplers, at their units
    // (common/bindings.h), for a pass that reads them outside draw() (a compute pass).
    void bindMaterialTextures(int objectIndex) const;
    BaseColorDetail baseColorDetail(int objectIndex) const;

private:
    // The last pass's view-projection, for the STRATA_DEBUG_* experiments in gpu_scene.cpp.
    mutable glm::mat4 debugViewProjection_{1.0f};
    void uploadTextures();
    // The object's material's uniforms (and the light loop's count) on the program that draws it.
    void setMaterialUniforms(const SceneProgram& program, int objectIndex) const;
    // glUseProgram of the variant for the object's features, its textures bound; returns it.
    const SceneProgram& prepareVariant(const SceneProgram& program, int objectIndex) const;
    // The stand-ins of `objects`, all sameStandInBatch: one glMultiDrawArraysIndirect over
    // their slice ranges with an instance each.
    void drawStandIns(const SceneProgram& program, std::span<const int> objects, const StandInDraw& standIn) const;
    // The base instance of the records of `objects`: the first object's own when the indices
    // are consecutive, else a ring slot they are copied into.
    std::size_t recordsOf(std::span<const int> objects) const;

    Scene scene_;
    std::vector<Object> objects_;
    CullHierarchy cullHierarchy_;
    std::vector<GpuMesh> meshes_;
    std::vector<int> opaque_;
    std::vector<int> transparent_;
    std::vector<int> opaqueBatched_, transparentBatched_;
    std::vector<ObjectVolume> volumes_;
    std::vector<int> volumeEntry_;  // uVolumeEntry per object: 0 surface, +1/-1 entering faces
    std::vector<unsigned> features_;  // SceneFeature bits per object
    std::vector<glm::vec3> volumeFilter_;  // uVolumeFilter per object (scene/scene.hpp's volumeFilterOnEntry)
    bool coloredFilters_ = false;
    // Per Scene::images entry, mipmapped, in the encodings materials use it with (colour
    // textures sRGB, the others linear; an unused one has id 0).
    std::vector<gl::Texture> srgbTextures_, linearTextures_;
    // One GL sampler per distinct glTF sampler; materialSampler_ indexes it per material and
    // slot (-1 none).
    std::vector<std::pair<Sampler, gl::Sampler>> samplers_;
    std::vector<std::array<int, kMaterialSlots>> materialSampler_;
    std::size_t textureBytes_ = 0;
    gl::Buffer lights_;  // gpu::PunctualLight[kMaxLights], std140 (common/lighting.glsl)
    int lightCount_ = 0;
    // Per object, what the scene programs take (render/object_records.hpp), and the vertex buffer
    // the meshes' vertex arrays read them from as instanced attributes: records 0 .. objects-1
    // are the objects' own (a single draw's base instance is its object), the rest a ring that
    // drawObjects copies each run's records into.
    std::vector<gpu::ObjectRecord> records_;
    gl::Buffer recordBuffer_;
    mutable std::vector<gpu::ObjectRecord> runScratch_;
    std::size_t streamRing_ = 0;            // entries in the ring
    mutable std::size_t streamHead_ = 0;    // next free ring entry
    mutable std::uint64_t drawCalls_ = 0;
    // Stand-in batches' indirect commands (DrawArraysIndirectCommand), a ring like the records'.
    mutable gl::Buffer indirect_;
    mutable std::size_t indirectHead_ = 0, indirectCapacity_ = 0;
    mutable std::vector<GLuint> indirectScratch_;
    Bounds bounds_;
    std::size_t triangles_ = 0;
    std::size_t meshTriangles_ = 0, meshBytes_ = 0;
};

}  // namespace strata
