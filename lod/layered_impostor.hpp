#pragma once
// A layered impostor of one mesh (Schaufler sections 3-4): RGBz images from view directions on
// a platonic solid, each with the back-perspective projection of impostor_frame.hpp, baked on
// the GPU into one RGBA8 2D-array atlas; per (view, peel, slice) the bounding rectangle of the
// texels the slice accepts (Fig. 6 left) and one vertex buffer of all non-empty slice quads;
// hole filling by the id-render preprocessing of section 3.3. Per frame, drawFor() picks the
// ranges to draw (nearest view in full, the hole-closing slices of the two other nearest views)
// as a StandInDraw that the scene passes draw in the object's place (lod-contract.md).
//
// With a BakeMaterial the bake also keeps the material's base colour texture x COLOR_0 (colour
// and alpha) per texel in a second atlas (sRGB RGBA8, same layers), and a MASK material's texels
// below the cutoff are no surface: a textured, vertex-coloured or cut-out object looks the same
// as its impostor (its factors still shade it per draw).
//
// Atlas convention (lod-contract.md): layer = view * peels + peel; rgb = object-space normal *
// 0.5 + 0.5; a = depth code / 255, code 0 empty, else t = (code - 0.5) / 255 over the slab
// (t = 0 nearest the apex). The surface kept is the one FARTHEST from the apex (nearest a viewer
// on the view's side); transparent meshes keep `peels` surfaces per texel, peeling towards the
// apex, with overlap forced to 0 so that no surface is emitted twice.
#include "gl/objects.hpp"
#include "lod/impostor_frame.hpp"
#include "lod/impostor_memory.hpp"
#include "render/gpu_scene.hpp"
#include "render/stand_in.hpp"
#include "scene/scene.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace strata::lod {

struct ImpostorSettings {
    int views = 20;          // 12, 20 or 32 (view_directions.hpp)
    int resolution = 128;    // image side in texels, 1..256 (a rectangle's extents are bytes)
    int slices = 64;         // L, 1..256
    float overlap = 0.5f;    // slice widths each slice's depth interval reaches past its own, each side
    int peels = 1;           // surfaces kept per texel: 1 opaque, 1..4 transparent (overlap then 0)
    float apexFactor = kDefaultApexFactor;  // D = apexFactor * r, > 1
    bool holeFilling = true; // run the id-render preprocessing (else drawFor never fills holes)
    // Build the levels of merged slices (levels()) beside the baked ones. Not part of what a bake
    // is (no cache key, not stored): the levels come from the images on bake and on load.
    bool mergedLevels = false;

    // Empty when usable, else why not (one line).
    std::string validate() const;
};

// The object whose material a bake keeps (GpuScene::baseColorDetail; its textures bound by
// GpuScene::bindMaterialTextures). Every object that draws the impostor must share what the
// bake keeps of it (lod/impostor_set.hpp keys impostors so).
struct BakeMaterial {
    const GpuScene* scene = nullptr;  // null: normals and depths only
    int objectIndex = -1;
};

// One part of what a bake draws: a mesh's vertex array (attribute 0 position, 1 normal, indexed
// triangles) placed by `transform` in the impostor's space. A LOD unit of several parts
// (lod/lod_units.hpp) bakes them all into one impostor, in its representative's space.
struct BakePart {
    GLuint vertexArray = 0;
    GLsizei indexCount = 0;
    glm::mat4 transform{1.0f};
    int objectIndex = -1;  // whose material detail the albedo keeps (BakeMaterial's scene set)
};

// Inclusive texel extents of the texels one slice accepts; x0 > x1 when it accepts none.
struct SliceRect {
    std::uint8_t x0 = 1, y0 = 1, x1 = 0, y1 = 0;
    bool empty() const { return x0 > x1; }
};
static_assert(sizeof(SliceRect) == 4, "the paper's 4 bytes per rectangle");

class LayeredImpostor {
public:
    // Bakes now on the current GL context: `mesh`'s vertex array (attribute 0 position, 1
    // normal, indexed triangles) inside `bounds` (object space). A mesh with no triangles, empty
    // or zero-radius bounds, or invalid settings gives no impostor: valid() false, reason() says
    // why. Nothing throws for those; a GL failure is reported by the caller's checkGl as usual.
    LayeredImpostor(const GpuMesh& mesh, const Bounds& bounds, const ImpostorSettings& settings,
                    BakeMaterial material = {});
    LayeredImpostor(GLuint vertexArray, GLsizei indexCount, const Bounds& bounds, const ImpostorSettings& settings,
                    BakeMaterial material = {});
    // Bakes several parts, each with its own material detail where `albedoScene` is set (a part of
    // an object without any draws white albedo: its factors shade it); `bounds` holds them all in
    // the impostor's space.
    LayeredImpostor(const std::vector<BakePart>& parts, const Bounds& bounds, const ImpostorSettings& settings,
                    const GpuScene* albedoScene = nullptr);
    LayeredImpostor(LayeredImpostor&&) noexcept = default;

    // The baked state as bytes (an on-disk cache's file, impostor_cache.hpp): the settings, the
    // bounding sphere, the atlas's and the albedo's texels, the rectangles and the hole-filling
    // slices; the frames, quads and vertex buffer are rebuilt from those on load. Valid impostors only.
    std::vector<std::uint8_t> serialize() const;
    // An impostor from serialize()'s bytes, uploaded on the current GL context (no bake: bakeMs is
    // the load's time). Throws std::runtime_error naming what is malformed: the bytes may come
    // from a file another version wrote or a disk damaged.
    static LayeredImpostor deserialize(std::span<const std::uint8_t> bytes, bool mergedLevels = false);
    LayeredImpostor& operator=(LayeredImpostor&&) noexcept = default;

    bool valid() const { return reason_.empty(); }
    const std::string& reason() const { return reason_; }
    // As used: overlap is 0 when peels > 1.
    const ImpostorSettings& settings() const { return settings_; }

    // The ranges to draw for an eye at `eyeInObjectSpace`: every non-empty slice of the nearest
    // view (all its peels) and, with fillHoles, the slices of the two other nearest views that
    // the preprocessing found closing that view's holes. An eye at the centre uses view 0.
    // `level` (0..levels() - 1) draws that level's merged slices. Empty ranges when !valid().
    StandInDraw drawFor(const glm::vec3& eyeInObjectSpace, bool fillHoles = true, int level = 0) const;

    // Levels of merged slices, from the same images (no bake of their own): level l has
    // levelSlices(l) = slices / 2^l slices, each accepting the depth codes of 2^l neighbouring
    // ones (overlap in its own widths), with its own rectangles and quads in the same vertex
    // buffer. The images hold one depth code per texel, so a slice is only a quad at a depth
    // that accepts the codes in its interval: merging needs no new texels. Level 0 is the baked
    // count; with settings().mergedLevels, coarser levels go down to kLeastLevelSlices while the
    // count halves exactly (else there is level 0 alone). A far
    // stand-in whose error bound allows it draws a coarser level: fewer, larger quads, whose cost
    // follows the count (lod_select.hpp).
    static constexpr int kLeastLevelSlices = 8;
    int levels() const { return int(levels_.size()); }
    int levelSlices(int level) const { return levels_[std::size_t(level)].slices; }
    // The view error: angle in radians between the direction centre -> eye and the nearest view.
    float nearestViewAngle(const glm::vec3& eyeInObjectSpace) const;
    int nearestView(const glm::vec3& eyeInObjectSpace) const;

    // Images and rectangles exactly per the formulas (impostor_memory.hpp), the vertex buffer apart.
    ImpostorMemory bytes() const;
    int quadCount(int level = 0) const { return valid() ? levels_[std::size_t(level)].quads : 0; }
    double bakeMs() const { return bakeMs_; }

    const std::vector<glm::vec3>& directions() const { return directions_; }
    const ImpostorFrame& frame(int view) const { return frames_[std::size_t(view)]; }
    glm::vec3 centre() const { return centre_; }
    float radius() const { return radius_; }
    // Of a level's (view, peel, slice), slice < levelSlices(level).
    SliceRect rectangle(int view, int peel, int slice, int level = 0) const {
        return levels_[std::size_t(level)].rects[rangeIndex(view, peel, slice, level)];
    }
    // Vertex range of one (view, peel, slice): count 0 when the slice is empty.
    std::pair<GLint, GLsizei> sliceRange(int view, int peel, int slice, int level = 0) const;
    // The adjacent pairs (V, Vi) the preprocessing ran, and for each the slices of Vi (as
    // peel * slices + slice) that showed through V's holes (pixels the mesh covers and V's
    // impostor does not) from the direction halfway between. A coarser level's are the merged
    // slices holding those (slice / 2^l).
    const std::vector<std::pair<int, int>>& adjacency() const { return adjacency_; }
    const std::vector<int>& holeSlices(int view, int adjacentView, int level = 0) const;

    // Opaque impostors store and draw each view's slices nearest its viewer first (slice L - 1,
    // farthest from the apex, first): a deeper slice's texels behind a nearer slice's surface
    // then fail the early depth test and are never shaded (llvmpipe, like a GPU, tests depth
    // before a shader that only discards). Transparent ones keep the apex's order, back to
    // front, the order blending needs. A transparent impostor always has overlap 0 (ImpostorSet
    // sets it, so that no surface is blended twice), with one peel or more; one peel and an
    // overlap is therefore opaque. An opaque one baked with overlap 0 keeps the apex's order:
    // right, without the saving.
    bool frontToBack() const { return settings_.peels == 1 && settings_.overlap > 0.0f; }
    // The slice drawn k-th (0..L - 1) of a view's L.
    int sliceAt(int k, int L) const { return frontToBack() ? L - 1 - k : k; }
    GLuint atlas() const { return atlas_.id(); }
    GLuint albedo() const { return albedo_.id(); }  // 0 without a BakeMaterial
    GLuint vertexArray() const { return quadArray_.id(); }

private:
    LayeredImpostor() = default;
    // An array texture of `layers` square images, nearest-sampled, clamped: the atlas and albedo.
    static gl::Texture layerTexture(GLenum format, int resolution, int layers);
    // Every layer of an atlas-shaped texture (the atlas or the albedo) as RGBA8 bytes.
    std::vector<std::uint8_t> readLayers(GLuint texture) const;
    std::size_t rangeIndex(int view, int peel, int slice, int level = 0) const {
        return (std::size_t(view) * std::size_t(settings_.peels) + std::size_t(peel)) *
                   std::size_t(levels_[std::size_t(level)].slices) +
               std::size_t(slice);
    }
    void bakeImages(const std::vector<BakePart>& parts, const GpuScene* albedoScene);
    // Every level's rectangles from the images' depth codes (levels_ sized here); level 0's are
    // `baked` where given (a cache load has them stored).
    void buildRectangles(std::span<const std::uint8_t> texels, std::vector<SliceRect> baked = {});
    std::vector<SliceRect> rectanglesFor(std::span<const std::uint8_t> texels, int slices) const;
    void buildQuads();
    void findHoleSlices(const std::vector<BakePart>& parts);
    // The coarser levels' hole slices from level 0's.
    void mergeHoleSlices();

    ImpostorSettings settings_;
    std::string reason_;
    glm::vec3 centre_{0.0f};
    float radius_ = 0.0f;
    std::vector<glm::vec3> directions_;
    std::vector<ImpostorFrame> frames_;
    gl::Texture atlas_, albedo_;
    gl::Buffer quadBuffer_;
    gl::VertexArray quadArray_;
    struct Level {
        int slices = 0;
        std::vector<SliceRect> rects;    // per rangeIndex
        std::vector<GLint> first;        // per rangeIndex
        std::vector<GLsizei> count;      // per rangeIndex, 0 empty
        std::vector<GLint> viewFirst;    // per view: all its peels' quads are contiguous
        std::vector<GLsizei> viewCount;
        std::map<std::pair<int, int>, std::vector<int>> holeSlices;
        int quads = 0;
    };
    std::vector<Level> levels_;  // [0]: the baked slices; then each half the last
    std::vector<std::pair<int, int>> adjacency_;
    std::uint64_t vertexBytes_ = 0;
    double bakeMs_ = 0.0;
};

}  // namespace strata::lod
