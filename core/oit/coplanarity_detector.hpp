#pragma once
// The image-based coplanarity detector (Vasilakis and Fudos, Fig. 13) on the GPU: per pixel, the
// largest number of transparent fragments in one depth layer under the exact reference's tie rule
// (render/depth_order.hpp), as a count image (rg32ui: largest layer, and the pixel's fragments,
// by which a check tells coverage differences from layer differences), its Fig. 13 colours
// (linear rgba16f) and
// frame totals (render/coplanarity.hpp: C_p, and R_h of one-fragment-per-layer peeling).
//
// Why the A-buffer's lists: counting a layer needs every fragment of the pixel, and "one layer" is
// decided on sorted depths with a tolerance, not on bit-equal depths, which GPUs do not promise
// for coincident surfaces. So the store is abuffer's (shaders/oit/abuffer_store.frag.glsl) and
// the resolve sorts each list and counts (shaders/oit/coplanarity_detect.comp.glsl). Like
// abuffer, memory grows to the fragments present and the frame is split into tiles where they
// exceed the largest storage block: it works on any scene size and drops nothing.
//
// Runs inside a frame, after the opaque pass: it reads the opaque depth through the output
// framebuffer (frame/frame_renderer.cpp calls it when FrameOptions::detectCoplanarity is set).
#include "oit/fragment_lists.hpp"
#include "oit/technique.hpp"
#include "render/coplanarity.hpp"
#include "render/scene_program.hpp"

#include <cstdint>
#include <vector>

namespace strata {

class CoplanarityDetector {
public:
    // Its timed passes are named with this prefix, so a frame can report them apart from the
    // technique's time (FrameResult::coplanarityMs).
    static constexpr const char* kPassPrefix = "coplanarity ";

    // maxBlockMiB > 0 caps the node pool below the device's limit (tests force tiles with it).
    explicit CoplanarityDetector(double maxBlockMiB = 0.0) : maxBlockMiB_(maxBlockMiB) {}

    // Detects on this frame; the textures below then hold its result.
    CoplanarityStats detect(const FrameContext& frame);

    GLuint largestLayerTexture() const { return largestLayer_.id(); }  // rg32ui: largest layer, fragments
    GLuint heatmapTexture() const { return heatmap_.id(); }            // rgba16f, linear RGB
    glm::ivec2 size() const { return size_; }
    double maxBlockMiB() const { return maxBlockMiB_; }

    // Last frame's per-pixel figures, row 0 at the bottom.
    struct Pixels {
        std::vector<std::uint32_t> largestLayer;
        std::vector<std::uint32_t> fragments;
    };
    Pixels readPixels() const;
    Image readHeatmap() const;

    // What the last detect() cost: passes issued, GPU memory held, tiles it was split into,
    // times the pool grew and a tile was stored again.
    int passes() const { return passes_; }
    std::uint64_t bytes() const;
    int tiles() const { return tiles_; }
    int regrows() const { return regrows_; }

private:
    void prepare(glm::ivec2 size);
    void resolve(const FrameContext& frame, const FragmentLists::Tile& tile);

    double maxBlockMiB_;
    FragmentLists lists_{"coplanarity"};
    SceneProgram storeProgram_;
    gl::Program resolveProgram_;
    GLint tileLocation_ = -1;
    gl::Buffer totals_;
    gl::Texture largestLayer_, heatmap_;
    glm::ivec2 size_{0, 0};
    int passes_ = 0, tiles_ = 0, regrows_ = 0;
};

}  // namespace strata
