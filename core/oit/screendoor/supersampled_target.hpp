#pragma once
// The n x n supersampled frame the screen-door techniques render into (Sen et al. 4.1.3): its
// colour and depth start as the opaque image replicated n x n per pixel, the masked transparent
// fragments are drawn into it as opaque fragments with the z-buffer on, and it is box-filtered
// down to the output by repeated 2x2 averaging, as mip-map generation does.
//
// A frame larger than kMaxSupersampledSide samples a side is rendered in tiles of the output,
// each through a projection that maps the tile to the whole viewport, so memory stays bounded
// (n = 16 at 1080p would be 30720 x 17280 samples in one piece).
#include "gl/objects.hpp"
#include "oit/technique.hpp"

#include <glm/glm.hpp>

#include <optional>
#include <vector>

namespace strata::screendoor {

// Largest supersampled side of one tile: 2048^2 samples hold 64 MiB of RGBA32F colour, 21 MiB
// of its 2x2 averages and 16 MiB of depth.
inline constexpr int kMaxSupersampledSide = 2048;

struct Tile {
    glm::ivec2 origin{0};  // output pixels
    glm::ivec2 size{0};
};

// The output split into tiles whose supersampled size fits kMaxSupersampledSide.
std::vector<Tile> supersampleTiles(glm::ivec2 frameSize, int factor);

// The clip-space remap that makes `tile` of a `frameSize` frame fill the viewport.
glm::mat4 tileClipTransform(glm::ivec2 frameSize, const Tile& tile);

class SupersampledTarget {
public:
    // Allocates for `tile` at `factor` (a power of two), fills colour and depth from the frame's
    // opaque targets, and leaves its framebuffer bound with the viewport set and the depth test
    // (GL_GREATER) writing: what a masked fragment needs. Only `area` (output pixels within the
    // tile; the whole tile by default) is filled, and the scissor is left on around its samples
    // for the draw.
    void begin(const FrameContext& frame, const Tile& tile, int factor, std::optional<PixelRect> area = {});
    // Averages 2x2 blocks log2(factor) times; the last average writes the tile of the output.
    // Only `area` (as for begin) is averaged and written; the scissor is off afterwards.
    void resolve(const FrameContext& frame, const Tile& tile, int factor, std::optional<PixelRect> area = {});
    // Full-screen passes per tile: the fill and the averages (a copy when factor is 1).
    static int passesPerTile(int factor);
    std::uint64_t bytes() const;

private:
    void allocate(glm::ivec2 samples, int levels);

    gl::Texture color_, depth_;
    gl::Framebuffer samplesFbo_, averageFbo_;
    gl::Program fill_, average_;
    glm::ivec2 allocated_{0};
    int levels_ = 0;
};

}  // namespace strata::screendoor
