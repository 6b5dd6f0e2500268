#pragma once
// What every screen-door technique does around its masking draw: bind the random masks, then
// per tile fill the supersampled frame from the opaque image, let the technique draw (a fragment
// its mask rejects is discarded, one it keeps is written opaque with the z-buffer on), and
// box-filter the tile into the output. No sorting, no blending: the image depends only on which
// samples each surface keeps and on depth.
#include "oit/screendoor/alpha_masks.hpp"
#include "oit/screendoor/supersampled_target.hpp"
#include "oit/technique.hpp"

#include <cstdint>
#include <functional>

namespace strata::screendoor {

struct PassParameters {
    int factor = 4;          // n of the n x n supersampling (a power of two)
    int maskSide = 128;      // 0: the technique uses no masks
    std::uint32_t seed = 1;
    const char* name = "screendoor";  // timer pass names
};

// Sets on `program` (when it declares them): uSeed, uSamplesPerUnit (supersampled pixels per
// scene unit at unit depth: h_im / (2 tan(fov / 2))), uEyePosition, uViewAxis, uViewRight, uNearPlane.
void setSamplingUniforms(GLuint program, const FrameContext& frame, const PassParameters& parameters);

// Draws one tile: `tileFrame` carries the tile's view-projection, `tileOriginSamples` is the
// tile's first sample in the whole supersampled frame. Returns the draw calls issued.
using DrawTile = std::function<std::uint64_t(const FrameContext& tileFrame, glm::ivec2 tileOriginSamples)>;

// Draws masked scene objects with `program` (drawTransparent per tile).
DrawTile drawMaskedObjects(const SceneProgram& program);

class ScreenDoorPass {
public:
    TechniqueStats render(const FrameContext& frame, const PassParameters& parameters, const DrawTile& draw);

private:
    AlphaMasks masks_;
    SupersampledTarget target_;
    gl::Query samples_;
};

}  // namespace strata::screendoor
