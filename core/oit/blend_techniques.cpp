// The blending baselines: one geometry pass with fixed-function "over" blending, in submission
// order (blend-unsorted) or with objects sorted back to front (blend-sorted). Both are exact only
// when no two objects overlap out of order; neither resolves intersecting or coplanar surfaces.
//
// In a scene with coloured filters (oit/color_model.hpp) both blend a glass fragment's filter
// per channel by dual-source blending (blend.frag.glsl): no target more, no pass more.
//
// precision=32 blends straight into the RGBA32F output. precision=16 blends into an RGBA16F
// scratch target sharing the opaque depth: the opaque colour is blitted in, the pass blends,
// and the result is blitted back (two full-screen copies against one float32 blend per
// fragment).
#include "oit/color_model.hpp"
#include "oit/draw_transparent.hpp"
#include "oit/precision.hpp"
#include "oit/scratch_target.hpp"
#include "oit/technique.hpp"


namespace strata {
namespace {

struct BlendSettings {
    int precision = 32;
    static const SettingsSchema<BlendSettings>& schema() {
        static const SettingsSchema<BlendSettings> s{precisionSetting(&BlendSettings::precision, "blend target")};
        return s;
    }
};

class BlendTechnique final : public TechniqueWithSettings<BlendSettings> {
public:
    BlendTechnique(TechniqueInfo info, bool sorted) : TechniqueWithSettings(std::move(info)), sorted_(sorted) {}

    void render(const FrameContext& frame) override {
        const ColorModel model = colorModelFor(frame.scene);
        SceneProgram& program = programs_.use(model).blend;
        if (!program.program) program = buildSceneProgram("oit/blend.frag.glsl", withColorModel({}, model));
        std::vector<int> order = sorted_ ? sortedBackToFront(frame) : frame.transparentOrder;
        const bool half = isHalf(settings_.precision);
        stats_ = {};
        stats_.passes = 1;
        gl::ScopedPass pass(frame.timer, "blend");
        GLuint target = frame.targets.outputFramebuffer();
        if (half) {
            target = scratch_.bind(frame.targets, frame.size, GL_RGBA16F, info_.id.c_str());
            copyColor(frame, frame.targets.outputFramebuffer(), target);
        }
        glBindFramebuffer(GL_FRAMEBUFFER, target);
        setTransparentDepthState(frame);
        glEnable(GL_BLEND);
        if (model == ColorModel::RgbTransmittance)
            glBlendFuncSeparate(GL_ONE, GL_SRC1_COLOR, GL_ZERO, GL_ONE);
        else
            glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
        // Every fragment that passes the depth test is blended: an occlusion query counts them.
        if (!samples_) samples_ = gl::createQuery(GL_SAMPLES_PASSED);
        glBeginQuery(GL_SAMPLES_PASSED, samples_.id());
        stats_.objectDraws = drawTransparent(frame, program, order);
        glEndQuery(GL_SAMPLES_PASSED);
        glDisable(GL_BLEND);
        // A dual-source blend function left set makes a later draw into several targets an error
        // on Mesa, blending enabled or not.
        glBlendFunc(GL_ONE, GL_ZERO);
        if (half) copyColor(frame, target, frame.targets.outputFramebuffer());
        const std::uint64_t blended = gl::queryResult(samples_);
        stats_.fragmentsCaptured = blended;
        stats_.bytes = half ? std::uint64_t(frame.size.x) * frame.size.y * floatTexelBytes(settings_.precision, 4) : 0;
    }

private:
    static void copyColor(const FrameContext& frame, GLuint from, GLuint to) {
        glBlitNamedFramebuffer(from, to, 0, 0, frame.size.x, frame.size.y, 0, 0, frame.size.x, frame.size.y,
                               GL_COLOR_BUFFER_BIT, GL_NEAREST);
    }

    struct Programs {
        SceneProgram blend;
    };
    bool sorted_;
    ProgramsPerColorModel<Programs> programs_;  // oit/color_model.hpp
    gl::Query samples_;
    ScratchTarget scratch_;
};

}  // namespace

TechniqueEntry blendUnsortedEntry() {
    TechniqueInfo info{"blend-unsorted", "baseline", false, false, "1",
                       "w*h*8 RGBA16F scratch at precision=16; none at 32 (blends into the output)",
                       "alpha blending in submission order (wrong wherever objects arrive front to back)"};
    info.rgbTransmittance = true;
    info.keepsSubmissionOrder = true;
    return techniqueEntry<BlendTechnique>(info, false);
}

TechniqueEntry blendSortedEntry() {
    TechniqueInfo info{"blend-sorted", "baseline", false, false, "1",
                       "w*h*8 RGBA16F scratch at precision=16; none at 32 (blends into the output)",
                       "alpha blending with objects sorted back to front by bounds centre"};
    info.rgbTransmittance = true;
    info.keepsSubmissionOrder = true;
    return techniqueEntry<BlendTechnique>(info, true);
}

}  // namespace strata
