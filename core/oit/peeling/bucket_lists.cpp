// `bun-ll`: bucket peeling combined with linked lists (depth-fighting paper, section 3.1.4). A
// range pass (bucket_range.hpp, shared with `bun`) gives each pixel's depth range; one store
// pass links every fragment into the list of its uniform depth bucket (B heads per pixel, one
// node pool grown to the fragments: fragment_lists.hpp, as abuffer, so nothing overflows and
// frames past the largest storage block are split in tiles); a resolve composites the buckets
// near to far, each post-sorted, with the project's tie rule across the whole pixel. Unlike
// `bun`, a bucket holds any number of fragments, coincident ones included: robust.
#include "oit/technique.hpp"

#include "common/bindings.h"
#include "oit/color_model.hpp"
#include "oit/draw_transparent.hpp"
#include "oit/fragment_lists.hpp"
#include "oit/peeling/bucket_range.hpp"
#include "oit/peeling/peel_bindings.h"

namespace strata::peeling {
namespace {

constexpr int kMaxBuckets = 32;  // MAX_BUCKETS of bun_ll_resolve.frag.glsl

struct BucketListSettings {
    int buckets = 8;
    bool rangeFromGeometry = false;
    int initialNodes = 0;
    double maxBlockMiB = 0;
    static const SettingsSchema<BucketListSettings>& schema() {
        using S = BucketListSettings;
        static const SettingsSchema<S> s{
            integerSetting(&S::buckets, "buckets", 1, kMaxBuckets, SettingChange::Reallocate,
                           "uniform depth buckets per pixel, one linked list (head) each"),
            flagSetting(&S::rangeFromGeometry, "range_from_geometry", SettingChange::Nothing,
                        "the depth range from the geometry (one more geometry pass, tighter buckets) instead of the "
                        "objects' bounding boxes"),
            integerSetting(&S::initialNodes, "initial_nodes", 0, 1000000000, SettingChange::Reallocate,
                           "node pool capacity on the first frame (0: two per pixel); it grows as needed"),
            realSetting(&S::maxBlockMiB, "max_block_mib", 0, 1e6, SettingChange::Reallocate,
                        "largest node pool in MiB (0: the device's GL_MAX_SHADER_STORAGE_BLOCK_SIZE); past it the "
                        "frame is stored and resolved in tiles"),
        };
        return s;
    }
};

class BucketLists final : public TechniqueWithSettings<BucketListSettings> {
public:
    explicit BucketLists(TechniqueInfo info) : TechniqueWithSettings(std::move(info)), lists_(info_.id) {}

    void render(const FrameContext& frame) override {
        const ColorModel model = colorModelFor(frame.scene);
        programs_.use(model);
        if (!programs_->store.program) {
            programs_->store = buildSceneProgram("oit/peeling/bun_ll_store.frag.glsl", withColorModel({}, model));
            programs_->resolve = gl::buildProgram({"common/fullscreen.vert.glsl", "oit/peeling/bun_ll_resolve.frag.glsl"},
                                                  withColorModel({{"MAX_BUCKETS", std::to_string(kMaxBuckets)}}, model));
        }
        stats_ = {};
        const int buckets = settings_.buckets;
        range_.render(frame, settings_.rangeFromGeometry, stats_);
        const GLuint store = programs_->store.id(), resolve = programs_->resolve.id();
        glProgramUniform1i(store, glGetUniformLocation(store, "uBuckets"), buckets);
        glProgramUniform1f(store, glGetUniformLocation(store, "uDepthA"), frame.projection[2][2]);
        glProgramUniform1f(store, glGetUniformLocation(store, "uDepthB"), frame.projection[3][2]);
        glProgramUniform1i(resolve, glGetUniformLocation(resolve, "uBuckets"), buckets);
        setDepthOrderUniforms(frame, resolve);
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
        glBindTextureUnit(gpu::BIND_PEEL_PREVIOUS, range_.texture());
        glBindTextureUnit(gpu::BIND_OPAQUE_DEPTH, frame.targets.depth());
        lists_.setHeadLayers(buckets);
        int resolves = 0;
        const FragmentLists::Run run =
            lists_.render(frame, programs_->store, std::uint64_t(settings_.initialNodes), settings_.maxBlockMiB,
                          [&](const FragmentLists::Tile& tile) {
                              composite(frame, tile);
                              ++resolves;
                          });
        stats_.passes += run.passes + resolves;
        stats_.fragmentsCaptured = run.fragments;
        stats_.tiles = run.tiles;
        stats_.regrows = run.regrows;
        stats_.objectDraws += run.objectDraws;
        const std::uint64_t pixels = std::uint64_t(frame.size.x) * std::uint64_t(frame.size.y);
        stats_.bytes = lists_.bytes() + pixels * BucketRange::kBytesPerPixel;
    }

private:
    void composite(const FrameContext& frame, const FragmentLists::Tile& tile) {
        gl::ScopedPass pass(frame.timer, info_.id + " resolve");
        glBindFramebuffer(GL_FRAMEBUFFER, frame.targets.outputFramebuffer());
        glDisable(GL_BLEND);
        glBindTextureUnit(gpu::BIND_OPAQUE_COLOR, frame.targets.opaqueColor());
        // The tile's pixels where transparent objects can lie: the output holds the opaque colour
        // elsewhere.
        TransparentAreaScissor scissor(frame, PixelRect{tile.origin, tile.size});
        drawFullscreen(frame, programs_->resolve.id());
    }

    struct Programs {
        SceneProgram store;
        gl::Program resolve;
    };
    ProgramsPerColorModel<Programs> programs_;  // oit/color_model.hpp
    BucketRange range_;
    FragmentLists lists_;
};

}  // namespace
}  // namespace strata::peeling

namespace strata {

TechniqueEntry bunLlEntry() {
    TechniqueInfo info{"bun-ll", "coplanarity", true, true, "3 per tile (range + store + resolve; +1 store per regrow)",
                       "w*h*(8 + 4B) (range, B heads) + 24 B per fragment, pool grown to the fragments present; "
                       "Table 1: 3C(Zall)+8 to 15C(Zall)+8 words",
                       "BUN-LL: uniform depth buckets of linked lists in one pass, each bucket post-sorted; exact "
                       "ties by the project's rule, across bucket boundaries too"};
    info.rgbTransmittance = true;
    return techniqueEntry<peeling::BucketLists>(info);
}

}  // namespace strata
