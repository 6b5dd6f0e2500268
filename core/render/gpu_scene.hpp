#pragma once
// The scene on the GPU: one vertex array per mesh, the flattened objects split into opaque and
// transparent lists, and the draw call every pass uses.
#include "gl/objects.hpp"
#include "render/scene_program.hpp"
#include "render/stand_in.hpp"
#include "scene/mesh_volume.hpp"
#include "scene/scene.hpp"

#include <glm/glm.hpp>

#include <vector>

namespace strata {

struct GpuMesh {
    gl::VertexArray vertexArray;
    gl::Buffer vertices;   // interleaved position, normal (6 floats)
    gl::Buffer indices;    // uint32
    GLsizei indexCount = 0;
};

// Uploads one mesh in the layout every scene program reads (attributes 0 position, 1 normal).
// Throws when the normals do not match the positions.
GpuMesh uploadMesh(const Mesh& mesh);

class GpuScene {
public:
    explicit GpuScene(Scene scene);

    const Scene& scene() const { return scene_; }
    const std::vector<Object>& objects() const { return objects_; }
    const std::vector<int>& opaqueObjects() const { return opaque_; }
    const std::vector<int>& transparentObjects() const { return transparent_; }
    bool hasTransparency() const { return !transparent_.empty(); }
    const Bounds& bounds() const { return bounds_; }
    // The mesh an object draws, for passes that read its buffers directly (vertex pulling).
    const GpuMesh& meshOf(int objectIndex) const { return meshes_[objects_[objectIndex].mesh]; }
    std::size_t triangleCount() const { return triangles_; }
    // What the volumetric techniques make of each object (indexed like objects()): a medium, or
    // why it is drawn as a surface. Computed once at construction.
    const std::vector<ObjectVolume>& objectVolumes() const { return volumes_; }

    // Sets the per-object uniforms (model, normal matrix, material with its volume parameters
    // tau and albedo, id, which faces enter a volume) on `program`, which must be bound, and
    // draws the object's triangles, or with `standIn` the stand-in's quads in their place.
    void draw(const SceneProgram& program, int objectIndex, const StandInDraw* standIn = nullptr) const;

    // Uniforms every scene program shares for a frame.
    void setFrameUniforms(const SceneProgram& program, const glm::mat4& viewProjection) const;

private:
    void setObjectUniforms(const SceneProgram& program, int objectIndex) const;
    void drawStandIn(const SceneProgram& program, int objectIndex, const StandInDraw& standIn) const;

    Scene scene_;
    std::vector<Object> objects_;
    std::vector<GpuMesh> meshes_;
    std::vector<int> opaque_;
    std::vector<int> transparent_;
    std::vector<ObjectVolume> volumes_;
    std::vector<int> volumeEntry_;  // uVolumeEntry per object: 0 surface, +1/-1 entering faces
    Bounds bounds_;
    std::size_t triangles_ = 0;
};

}  // namespace strata
