// The two mask screen-door techniques of Sen, Chemudugunta, Gopi: one random binary mask per
// alpha level, masked fragments written opaque with the z-buffer on at n x n supersampling, then
// box-filtered down by repeated 2x2 averaging. Order independent, one geometry pass. They differ
// only in where the mask is looked up, which is the program's stages:
//   `screendoor` (image space, Fig. 1): the mask over the supersampled image, offset per object.
//     Its coverage is alpha per pixel whatever the slope: no silhouette opacity.
//   `screendoor-object` (section 4.2, hardware-assisted): a geometry stage maps the mask on each
//     triangle so one texel covers about one supersampled pixel at the triangle's distance
//     (4.2.1). Sampled nearest, a sample that many texels fall in (at a silhouette) would keep
//     one of them and show no silhouette opacity (the paper's section 5); the fragment stage
//     reads the mask across the sample's footprint and keeps the sample if any read is kept
//     (the Max filter the paper asks for), so silhouettes grow opaque as 1 - (1 - a)^n.
#include "oit/draw_transparent.hpp"
#include "oit/screendoor/screendoor_pass.hpp"
#include "oit/screendoor/screendoor_settings.hpp"
#include "oit/technique.hpp"

#include <string>
#include <vector>

namespace strata {
namespace screendoor {
namespace {

class MaskScreenDoor final : public TechniqueWithSettings<MaskSettings> {
public:
    MaskScreenDoor(TechniqueInfo info, std::vector<std::string> stages)
        : TechniqueWithSettings(std::move(info)), stages_(std::move(stages)) {}

    void render(const FrameContext& frame) override {
        if (!program_.program) program_ = buildSceneProgram(stages_);
        const PassParameters parameters{settings_.supersampling, settings_.mask_size, std::uint32_t(settings_.seed),
                                        info_.id.c_str()};
        setSamplingUniforms(program_.id(), frame, parameters);
        stats_ = pass_.render(frame, parameters, drawMaskedObjects(program_));
    }

private:
    std::vector<std::string> stages_;  // after the scene vertex stage
    SceneProgram program_;
    ScreenDoorPass pass_;
};

constexpr const char* kMaskMemory =
    "w*h*n^2*(16*4/3 + 4) B supersampled colour, averages and depth (tiles of 2048^2 samples) + side^2*256 B masks";

}  // namespace
}  // namespace screendoor

TechniqueEntry screendoorEntry() {
    TechniqueInfo info{"screendoor", "baseline", false, false, "(2 + log2 n) per tile", screendoor::kMaskMemory,
                       "image-space screen-door: a random stipple mask per alpha level, offset per object, "
                       "n x n supersampled and box-filtered"};
    return techniqueEntry<screendoor::MaskScreenDoor>(info,
                                                      std::vector<std::string>{"oit/screendoor/screendoor_image.frag.glsl"});
}

TechniqueEntry screendoorObjectEntry() {
    TechniqueInfo info{"screendoor-object", "baseline", false, false, "(2 + log2 n) per tile", screendoor::kMaskMemory,
                       "object-space screen-door (Sen et al. 4.2): random masks per alpha level mapped on each "
                       "triangle at one texel per sample, read across each sample's footprint (silhouette opacity), "
                       "n x n supersampled and box-filtered"};
    return techniqueEntry<screendoor::MaskScreenDoor>(
        info, std::vector<std::string>{"oit/screendoor/object_mask.geom.glsl", "oit/screendoor/screendoor_object.frag.glsl"});
}

}  // namespace strata
