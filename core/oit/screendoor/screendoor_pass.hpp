#pragma once
// What every screen-door technique does once it has a masking program: bind the random masks,
// then per tile fill the supersampled frame from the opaque image, draw the transparent objects
// through the program (a fragment that its mask rejects is discarded, one it keeps is written
// opaque with the z-buffer on), and box-filter the tile into the output. No sorting, no blending:
// the image depends only on which samples each surface keeps and on depth.
#include "oit/screendoor/alpha_masks.hpp"
#include "oit/screendoor/supersampled_target.hpp"
#include "oit/technique.hpp"

#include <cstdint>

namespace strata::screendoor {

struct PassParameters {
    int factor = 4;          // n of the n x n supersampling (a power of two)
    int maskSide = 128;
    std::uint32_t seed = 1;
    const char* name = "screendoor";  // timer pass names
};

class ScreenDoorPass {
public:
    // Sets on `program` (when it declares them): uSeed, uTileOriginSamples (the tile's first
    // sample in the whole supersampled frame), uSamplesPerUnit (supersampled pixels per scene
    // unit at unit depth: h_im / (2 tan(fov / 2))), uEyePosition and uViewAxis.
    TechniqueStats render(const FrameContext& frame, const SceneProgram& program, const PassParameters& parameters);

private:
    AlphaMasks masks_;
    SupersampledTarget target_;
    gl::Query samples_;
};

}  // namespace strata::screendoor
