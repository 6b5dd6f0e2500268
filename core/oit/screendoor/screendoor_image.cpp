// `screendoor`: image-space screen-door transparency, the classic stipple baseline of Sen et al.
// (Fig. 1): per alpha level one random mask over the supersampled image, a random offset per
// object, masked fragments written opaque with the z-buffer on, then the box filter. Order
// independent, single geometry pass, but its coverage is alpha per pixel whatever the slope:
// no silhouette opacity.
#include "oit/draw_transparent.hpp"
#include "oit/screendoor/screendoor_pass.hpp"
#include "oit/screendoor/screendoor_settings.hpp"
#include "oit/technique.hpp"

namespace strata {
namespace screendoor {
namespace {

class ImageScreenDoor final : public TechniqueWithSettings<MaskSettings> {
public:
    using TechniqueWithSettings::TechniqueWithSettings;

    void render(const FrameContext& frame) override {
        if (!program_.program) program_ = buildSceneProgram("oit/screendoor/screendoor_image.frag.glsl");
        const PassParameters parameters{settings_.supersampling, settings_.mask_size, std::uint32_t(settings_.seed), "screendoor"};
        setSamplingUniforms(program_.id(), frame, parameters);
        stats_ = pass_.render(frame, parameters, drawMaskedObjects(program_));
    }

private:
    SceneProgram program_;
    ScreenDoorPass pass_;
};

}  // namespace
}  // namespace screendoor

TechniqueEntry screendoorEntry() {
    TechniqueInfo info{"screendoor", "baseline", false, false, "(2 + log2 n) per tile",
                       "w*h*n^2*(16*4/3 + 4) B supersampled colour, averages and depth (tiles of 2048^2 samples) "
                       "+ side^2*256 B masks",
                       "image-space screen-door: a random stipple mask per alpha level, offset per object, "
                       "n x n supersampled and box-filtered"};
    return techniqueEntry<screendoor::ImageScreenDoor>(info);
}

}  // namespace strata
