// Crow's baseline for silhouette opacity (Sen, Chemudugunta, Gopi, section 1): each fragment's
// opacity is a non-linear function of the normal's component towards the eye, rising from amin
// face-on to amax at the silhouette, and the objects are blended back to front like
// blend-sorted (so it shares blend-sorted's errors where objects overlap out of order). The
// formula is in shaders/oit/screendoor/crow.frag.glsl.
#include "oit/draw_transparent.hpp"
#include "oit/technique.hpp"

#include <glm/gtc/type_ptr.hpp>

namespace strata {
namespace {

struct CrowSettings {
    double amin = 0.3;
    double amax = 0.9;
    double power = 2.0;
    bool material_alpha = true;
    static const SettingsSchema<CrowSettings>& schema() {
        static const SettingsSchema<CrowSettings> s{
            realSetting(&CrowSettings::amin, "amin", 0.0, 1.0, SettingChange::Nothing,
                        "opacity face-on (|N_z| = 1); used when material_alpha is off"),
            realSetting(&CrowSettings::amax, "amax", 0.0, 1.0, SettingChange::Nothing,
                        "opacity at the silhouette (N_z = 0); never below the face-on opacity"),
            realSetting(&CrowSettings::power, "p", 0.125, 64.0, SettingChange::Nothing,
                        "Crow's cosine power: larger keeps the face-on opacity further towards the rim"),
            flagSetting(&CrowSettings::material_alpha, "material_alpha", SettingChange::Nothing,
                        "face-on opacity is each material's alpha (amin ignored)"),
        };
        return s;
    }
};

class Crow final : public TechniqueWithSettings<CrowSettings> {
public:
    using TechniqueWithSettings::TechniqueWithSettings;

    void render(const FrameContext& frame) override {
        if (!program_.program) {
            program_ = buildSceneProgram("oit/screendoor/crow.frag.glsl");
            samples_ = gl::createQuery(GL_SAMPLES_PASSED);
        }
        const GLuint p = program_.id();
        glProgramUniform3fv(p, glGetUniformLocation(p, "uEyePosition"), 1, glm::value_ptr(frame.camera.position));
        glProgramUniform1f(p, glGetUniformLocation(p, "uAlphaMin"), float(settings_.amin));
        glProgramUniform1f(p, glGetUniformLocation(p, "uAlphaMax"), float(settings_.amax));
        glProgramUniform1f(p, glGetUniformLocation(p, "uPower"), float(settings_.power));
        glProgramUniform1i(p, glGetUniformLocation(p, "uMaterialAlpha"), settings_.material_alpha ? 1 : 0);
        stats_ = {};
        stats_.passes = 1;
        gl::ScopedPass pass(frame.timer, "crow");
        glBindFramebuffer(GL_FRAMEBUFFER, frame.targets.outputFramebuffer());
        setTransparentDepthState(frame);
        glEnable(GL_BLEND);
        glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
        glBeginQuery(GL_SAMPLES_PASSED, samples_.id());
        stats_.objectDraws = drawTransparent(frame, program_, sortedBackToFront(frame));
        glEndQuery(GL_SAMPLES_PASSED);
        glDisable(GL_BLEND);
        const std::uint64_t blended = gl::queryResult(samples_);
        stats_.fragmentsCaptured = blended;
    }

private:
    SceneProgram program_;
    gl::Query samples_;
};

}  // namespace

TechniqueEntry crowEntry() {
    TechniqueInfo info{"crow", "baseline", false, false, "1", "none (blends into the output)",
                       "Crow's silhouette opacity: alpha from the normal against the view direction, "
                       "objects blended back to front"};
    info.keepsSubmissionOrder = true;  // sorted back to front like blend-sorted: ties keep object order
    return techniqueEntry<Crow>(info);
}

}  // namespace strata
