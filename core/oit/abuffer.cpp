// `abuffer`, the exact reference: every transparent fragment in front of the opaque depth goes
// into a per-pixel linked list, each list is sorted by (depth, object id, primitive id) and
// composited. Memory is grown to the counted fragments and the frame re-rendered until nothing
// overflows; where the fragments exceed the largest storage block the device allows, the frame
// is rendered in screen tiles, each within the limit. Nothing is ever dropped silently.
// `abuffer-volume` is the same storage with the volumetric resolve (oit/volume/): closed
// objects with a volume material render as media, exactly, with no capacity to choose.
#include "oit/technique.hpp"

#include "common/bindings.h"
#include "gl/debug.hpp"
#include "oit/color_model.hpp"
#include "oit/draw_transparent.hpp"
#include "oit/fragment_lists.hpp"
#include "oit/volume/volume_resolve.hpp"

#include <algorithm>
#include <memory>
#include <stdexcept>

namespace strata {
namespace {

struct ABufferSettings {
    int initialNodes = 0;
    double maxBlockMiB = 0;
    bool computeResolve = false;
    static const SettingsSchema<ABufferSettings>& schema() {
        static const SettingsSchema<ABufferSettings> s{
            integerSetting(&ABufferSettings::initialNodes, "initial_nodes", 0, 1000000000, SettingChange::Reallocate,
                           "node pool capacity on the first frame (0: two per pixel); it grows as needed"),
            realSetting(&ABufferSettings::maxBlockMiB, "max_block_mib", 0, 1e6, SettingChange::Reallocate,
                        "largest node pool in MiB (0: the device's GL_MAX_SHADER_STORAGE_BLOCK_SIZE)"),
            flagSetting(&ABufferSettings::computeResolve, "compute_resolve", SettingChange::Nothing,
                        "resolve in a compute dispatch instead of a full-screen fragment pass (same image)"),
        };
        return s;
    }
};

class ABuffer final : public TechniqueWithSettings<ABufferSettings> {
public:
    // volume: the volumetric store and resolve (VOLUME defined in the shaders).
    ABuffer(TechniqueInfo info, bool volume)
        : TechniqueWithSettings(std::move(info)),
          lists_(info_.id),
          volume_(volume ? std::make_unique<VolumeResolve>() : nullptr) {}

    void render(const FrameContext& frame) override {
        const ColorModel model = colorModelFor(frame.scene);
        // abuffer-volume without a volume object in the scene draws as abuffer (VolumeResolve::needed).
        walk_ = volume_ && VolumeResolve::needed(frame.scene);
        programs_[walk_].use(model);
        if (!programs()->store.program) {
            const gl::Defines defines = withColorModel(walk_ ? gl::Defines{{"VOLUME", ""}} : gl::Defines{}, model);
            programs()->store = buildSceneProgram("oit/abuffer_store.frag.glsl", defines);
            // The resolves read the nodes through the pool's buffer texture (oit/node_fetch.glsl).
            gl::Defines resolveDefines = defines;
            resolveDefines["NODE_TEXELS"] = "";
            programs()->resolve =
                gl::buildProgram({"common/fullscreen.vert.glsl", "oit/abuffer_resolve.frag.glsl"}, resolveDefines);
            programs()->computeResolve = gl::buildProgram({"oit/abuffer_resolve.comp.glsl"}, resolveDefines);
        }
        stats_ = {};
        if (walk_) volume_->prepare(frame);
        int resolves = 0;
        const FragmentLists::Run run =
            lists_.render(frame, programs()->store, std::uint64_t(settings_.initialNodes), settings_.maxBlockMiB,
                          [&](const FragmentLists::Tile& tile) {
                              resolve(frame, tile);
                              ++resolves;
                          });
        stats_.passes = run.passes + resolves;
        stats_.fragmentsCaptured = run.fragments;
        stats_.tiles = run.tiles;
        stats_.regrows = run.regrows;
        stats_.objectDraws = run.objectDraws;
        stats_.bytes = lists_.bytes();
        if (walk_) volume_->addStats(stats_);
    }

private:
    void resolve(const FrameContext& frame, const FragmentLists::Tile& tile) {
        if (settings_.computeResolve) {
            resolveCompute(frame, tile);
            return;
        }
        gl::ScopedPass pass(frame.timer, info_.id + " resolve");
        glBindFramebuffer(GL_FRAMEBUFFER,
                          walk_ ? volume_->colorFramebuffer(frame) : frame.targets.outputFramebuffer());
        glDisable(GL_BLEND);
        glBindTextureUnit(gpu::BIND_OPAQUE_COLOR, frame.targets.opaqueColor());
        const GLuint program = programs()->resolve.id();
        setDepthOrderUniforms(frame, program);
        if (walk_) volume_->bind(frame, program);
        glEnable(GL_SCISSOR_TEST);
        const PixelRect area = resolveArea(frame, tile);
        glScissor(area.origin.x, area.origin.y, area.size.x, area.size.y);
        drawFullscreen(frame, program);
    }

    // The pixels of `tile` a resolve writes: those where transparent objects can lie (the output
    // holds the opaque colour elsewhere), or the whole tile for abuffer-volume's walk, which
    // writes a target of its own.
    PixelRect resolveArea(const FrameContext& frame, const FragmentLists::Tile& tile) const {
        const PixelRect whole{tile.origin, tile.size};
        return walk_ ? whole : transparentAreaWithin(frame, whole);
    }

    void resolveCompute(const FrameContext& frame, const FragmentLists::Tile& tile) {
        gl::ScopedPass pass(frame.timer, info_.id + " resolve (compute)");
        const GLuint program = programs()->computeResolve.id();
        glBindImageTexture(gpu::BIND_RESOLVE_OUTPUT, frame.targets.outputColor(), 0, GL_FALSE, 0, GL_WRITE_ONLY,
                           GL_RGBA32F);
        glBindTextureUnit(gpu::BIND_OPAQUE_COLOR, frame.targets.opaqueColor());
        setDepthOrderUniforms(frame, program);
        if (walk_) volume_->bind(frame, program);
        const PixelRect area = resolveArea(frame, tile);
        glProgramUniform4i(program, glGetUniformLocation(program, "uTile"), area.origin.x, area.origin.y, area.size.x,
                           area.size.y);
        glUseProgram(program);
        constexpr int group = int(gpu::RESOLVE_GROUP_SIZE);
        glDispatchCompute(GLuint((area.size.x + group - 1) / group), GLuint((area.size.y + group - 1) / group), 1);
        // The output is read next as a texture or framebuffer attachment (blit, read-back).
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                        GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    }

    struct Programs {
        SceneProgram store;
        gl::Program resolve, computeResolve;
    };
    // The frame's programs: [walk_] then per colour model (oit/color_model.hpp).
    Programs* programs() const { return programs_[walk_].operator->(); }
    ProgramsPerColorModel<Programs> programs_[2];
    FragmentLists lists_;
    std::unique_ptr<VolumeResolve> volume_;  // abuffer-volume only
    bool walk_ = false;                      // this frame walks media (abuffer-volume with volumes)
};

}  // namespace

TechniqueEntry abufferEntry() {
    TechniqueInfo info{"abuffer", "reference", true, true, "2 per tile (+1 store per regrow)",
                       "w*h*4 heads + 24 B per fragment, pool grown to the fragments present",
                       "exact reference: per-pixel linked lists of every fragment, sorted by (depth, object, primitive)"};
    info.rgbTransmittance = true;
    return techniqueEntry<ABuffer>(info, false);
}

TechniqueEntry abufferVolumeEntry() {
    TechniqueInfo info{"abuffer-volume", "volumetric", true, true, "2 per tile (+1 store per regrow)",
                       "as abuffer, + 24 B per object (medium table)",
                       "the exact volumetric reference: abuffer's unbounded lists, resolved through the media of "
                       "closed volume objects (tau, albedo, Rayleigh in-scattering; Barta and Kovacs), other "
                       "transparent objects composited in the same walk (coloured filters per channel)"};
    info.rgbTransmittance = true;
    return techniqueEntry<ABuffer>(info, true);
}

}  // namespace strata
