// `screendoor-object-sw`: object-space screen-door transparency by point sampling, the software
// version of Sen, Chemudugunta, Gopi (section 4.1), here on the GPU: a compute pass lays a
// lattice of n = (N h_im / (d h))^2 A points on each triangle and keeps each with probability
// alpha; the kept points are drawn as one-sample points, opaque with the z-buffer on, at n x n
// supersampling, box-filtered down by repeated 2x2 averaging. Unlike the texture-mapped version
// every kept point is drawn, so a pixel where the surface turns away collects several of them:
// the silhouettes grow opaque. The point buffer is bounded (max_points); what does not fit is
// counted and reported as overflow.
#include "oit/screendoor/point_samples.hpp"
#include "oit/screendoor/screendoor_pass.hpp"
#include "oit/screendoor/screendoor_settings.hpp"
#include "oit/technique.hpp"

namespace strata {
namespace screendoor {
namespace {

struct PointSettings {
    int supersampling = 4;
    int seed = 1;
    int max_points_millions = 16;
    int max_triangle_samples = 1 << 18;
    static const SettingsSchema<PointSettings>& schema() {
        static const SettingsSchema<PointSettings> s{
            supersamplingSetting(&PointSettings::supersampling),
            seedSetting(&PointSettings::seed),
            integerSetting(&PointSettings::max_points_millions, "max_points_millions", 1, 256, SettingChange::Reallocate,
                           "most kept points held, in millions (28 B each); more are counted as overflow"),
            integerSetting(&PointSettings::max_triangle_samples, "max_triangle_samples", 1, 1 << 22,
                           SettingChange::Nothing,
                           "most lattice points on one triangle; a larger triangle gets a coarser lattice and is "
                           "counted as overflow"),
        };
        return s;
    }
};

class PointScreenDoor final : public TechniqueWithSettings<PointSettings> {
public:
    using TechniqueWithSettings::TechniqueWithSettings;

    void render(const FrameContext& frame) override {
        const PassParameters parameters{settings_.supersampling, 0, std::uint32_t(settings_.seed), "screendoor-object-sw"};
        PointSampling sampling;
        {
            gl::ScopedPass pass(frame.timer, "screendoor-object-sw sample");
            sampling = points_.sample(frame, parameters, std::uint64_t(settings_.max_points_millions) << 20,
                                      double(settings_.max_triangle_samples));
        }
        stats_ = pass_.render(frame, parameters, [this](const FrameContext& tileFrame, glm::ivec2) {
            points_.draw(tileFrame);
            return std::uint64_t(1);
        });
        stats_.passes += 1 + sampling.regrows;
        stats_.regrows = sampling.regrows;
        stats_.bytes += points_.bytes();
        stats_.fragmentsDropped = sampling.pointsWanted - sampling.pointsStored;
        stats_.primitivesBounded = sampling.trianglesBounded;
        stats_.overflowed = stats_.fragmentsDropped > 0 || sampling.trianglesBounded > 0;
    }

private:
    PointSamples points_;
    ScreenDoorPass pass_;
};

}  // namespace
}  // namespace screendoor

TechniqueEntry screendoorObjectSwEntry() {
    TechniqueInfo info{"screendoor-object-sw", "baseline", false, false, "1 + (2 + log2 n) per tile (+1 per regrow)",
                       "28 B per kept point (grown to fit, at most max_points_millions) + w*h*n^2*(16*4/3 + 4) B supersampled "
                       "(tiles of 2048^2 samples)",
                       "object-space screen-door by point sampling (Sen et al. 4.1): a lattice of one point per sample "
                       "on each triangle, kept with probability alpha, n x n supersampled; opaque silhouettes"};
    return techniqueEntry<screendoor::PointScreenDoor>(info);
}

}  // namespace strata
