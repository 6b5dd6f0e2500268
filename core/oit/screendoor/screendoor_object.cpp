// `screendoor-object`: object-space screen-door transparency, the hardware-assisted version of
// Sen, Chemudugunta, Gopi (section 4.2). Per alpha level one random binary mask; a geometry
// stage maps it on each triangle so one texel covers about one supersampled pixel at the
// triangle's distance (4.2.1); masked fragments are written opaque with the z-buffer on, at n x n
// supersampling, box-filtered down by repeated 2x2 averaging. Order independent and single pass.
// The mask is sampled nearest, so a pixel that many texels fall in (at a silhouette) still keeps
// one of them: this version shows no silhouette opacity (the paper's section 5).
#include "oit/draw_transparent.hpp"
#include "oit/screendoor/screendoor_pass.hpp"
#include "oit/screendoor/screendoor_settings.hpp"
#include "oit/technique.hpp"

namespace strata {
namespace screendoor {
namespace {

class ObjectScreenDoor final : public TechniqueWithSettings<MaskSettings> {
public:
    using TechniqueWithSettings::TechniqueWithSettings;

    void render(const FrameContext& frame) override {
        if (!program_.program)
            program_ = buildSceneProgram(std::vector<std::string>{"oit/screendoor/object_mask.geom.glsl",
                                                                  "oit/screendoor/screendoor_object.frag.glsl"});
        const PassParameters parameters{settings_.supersampling, settings_.mask_size, std::uint32_t(settings_.seed),
                               "screendoor-object"};
        setSamplingUniforms(program_.id(), frame, parameters);
        stats_ = pass_.render(frame, parameters, drawMaskedObjects(program_));
    }

private:
    SceneProgram program_;
    ScreenDoorPass pass_;
};

}  // namespace
}  // namespace screendoor

TechniqueEntry screendoorObjectEntry() {
    TechniqueInfo info{"screendoor-object", "baseline", false, false, "(2 + log2 n) per tile",
                       "w*h*n^2*(16*4/3 + 4) B supersampled colour, averages and depth (tiles of 2048^2 samples) "
                       "+ side^2*256 B masks",
                       "object-space screen-door (Sen et al. 4.2): random masks per alpha level mapped on each "
                       "triangle at one texel per sample, n x n supersampled and box-filtered"};
    return techniqueEntry<screendoor::ObjectScreenDoor>(info);
}

}  // namespace strata
