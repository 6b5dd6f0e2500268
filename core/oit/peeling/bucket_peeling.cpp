// `bun`: uniform bucket peeling (Liu, Huang, Liu and Wu 2009), approximate. Passes:
//   1. range: each pixel's depth range, from the transparent objects' bounding boxes (default,
//      "depth range from the bounds") or from the geometry (range_from_geometry=1), MAX-blended;
//   2. capture: the range is split into B uniform buckets of eye distance and each bucket keeps
//      its nearest and farthest depth by MAX blending across up to 8 RGBA32F targets (two
//      buckets per target, so B <= 2 x GL_MAX_DRAW_BUFFERS);
//   3. colour: the fragments whose depth matches a captured one store their colour in its slot;
//   4. composite: buckets near to far over the opaque colour.
// A bucket holding more than two fragments loses the ones between its extremes; coincident
// fragments race for one slot. Both are counted: captured is what the composite used,
// dropped = total (counted in pass 2) - captured.
#include "oit/technique.hpp"

#include "common/bindings.h"
#include "oit/color_model.hpp"
#include "oit/draw_transparent.hpp"
#include "oit/peeling/bucket_range.hpp"
#include "oit/peeling/peel_bindings.h"
#include "oit/precision.hpp"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <array>
#include <stdexcept>

namespace strata::peeling {
namespace {

constexpr int kMaxTargets = 8;

struct BucketPeelingSettings {
    int buckets = 8;
    bool rangeFromGeometry = false;
    int precision = 16;
    static const SettingsSchema<BucketPeelingSettings>& schema() {
        static const SettingsSchema<BucketPeelingSettings> s{
            integerSetting(&BucketPeelingSettings::buckets, "buckets", 1, 2 * kMaxTargets, SettingChange::Reallocate,
                           "uniform depth buckets per pixel (two fragments each)"),
            flagSetting(&BucketPeelingSettings::rangeFromGeometry, "range_from_geometry", SettingChange::Nothing,
                        "the depth range from the geometry (one more geometry pass, tighter buckets) instead of the "
                        "objects' bounding boxes"),
            precisionSetting(&BucketPeelingSettings::precision, "bucket colours (depths stay 32-bit)"),
        };
        return s;
    }
};

class BucketPeeling final : public TechniqueWithSettings<BucketPeelingSettings> {
public:
    using TechniqueWithSettings::TechniqueWithSettings;

    void render(const FrameContext& frame) override {
        GLint maxDrawBuffers = 0;
        glGetIntegerv(GL_MAX_DRAW_BUFFERS, &maxDrawBuffers);
        int buckets = settings_.buckets;
        int targets = (buckets + 1) / 2;
        if (targets > maxDrawBuffers)
            throw std::runtime_error("bun: " + std::to_string(buckets) + " buckets need " + std::to_string(targets) +
                                     " render targets, the device has " + std::to_string(maxDrawBuffers));
        const ColorModel model = colorModelFor(frame.scene);
        ensurePrograms(model);
        ensureTargets(frame.size, buckets, model);
        stats_ = {};
        const GLuint zeros[2] = {0, 0};
        glNamedBufferSubData(counters_.id(), 0, sizeof(zeros), zeros);
        glBindBufferBase(GL_ATOMIC_COUNTER_BUFFER, gpu::BIND_COUNTERS, counters_.id());
        glBindTextureUnit(gpu::BIND_OPAQUE_DEPTH, frame.targets.depth());
        setBucketUniforms(frame, captureProgram_.id(), buckets);
        setBucketUniforms(frame, colorProgram().id(), buckets);

        range_.render(frame, settings_.rangeFromGeometry, stats_);
        capture(frame);
        color(frame);
        composite(frame, buckets);

        glMemoryBarrier(GL_ATOMIC_COUNTER_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
        GLuint counts[2] = {0, 0};
        glGetNamedBufferSubData(counters_.id(), 0, sizeof(counts), counts);
        stats_.fragmentsCaptured = counts[1];
        stats_.fragmentsDropped = counts[0] > counts[1] ? counts[0] - counts[1] : 0;
        stats_.overflowed = stats_.fragmentsDropped > 0;
        std::uint64_t pixels = std::uint64_t(frame.size.x) * frame.size.y;
        // Range RG32F (8 B), ceil(B/2) RGBA32F bucket depths (16 B), 2B colours (RGBA16F, 8 B, or
        // RGBA32F, 16 B), and 2B filters besides with coloured filters.
        stats_.bytes = pixels * (8 + std::uint64_t(targets) * 16 +
                                 std::uint64_t(buckets) * colorSlotsPerBucket() * floatTexelBytes(settings_.precision, 4)) +
                       sizeof(zeros);
    }

private:
    int colorSlotsPerBucket() const { return model_ == ColorModel::RgbTransmittance ? 4 : 2; }

    void ensurePrograms(ColorModel model) {
        Programs& p = programs_.use(model);
        if (!p.composite) {
            p.color16 = buildSceneProgram("oit/peeling/bun_color.frag.glsl", withColorModel({{"COLOR_FORMAT", "rgba16f"}}, model));
            p.color32 = buildSceneProgram("oit/peeling/bun_color.frag.glsl", withColorModel({{"COLOR_FORMAT", "rgba32f"}}, model));
            p.composite = gl::buildProgram({"common/fullscreen.vert.glsl", "oit/peeling/bun_composite.frag.glsl"},
                                           withColorModel({}, model));
        }
        if (captureProgram_.program) return;
        captureProgram_ = buildSceneProgram("oit/peeling/bun_capture.frag.glsl", {{"MAX_TARGETS", std::to_string(kMaxTargets)}});
        counters_ = gl::Buffer::create();
        glNamedBufferStorage(counters_.id(), 2 * sizeof(GLuint), nullptr, GL_DYNAMIC_STORAGE_BIT | GL_MAP_READ_BIT);
    }

    void ensureTargets(glm::ivec2 size, int buckets, ColorModel model) {
        if (size == size_ && buckets == allocatedBuckets_ && settings_.precision == allocatedPrecision_ &&
            model == model_)
            return;
        size_ = size;
        allocatedBuckets_ = buckets;
        allocatedPrecision_ = settings_.precision;
        model_ = model;
        int targets = (buckets + 1) / 2;
        auto array = [&](GLenum format, int layers) {
            gl::Texture t = gl::createTexture(GL_TEXTURE_2D_ARRAY);
            glTextureStorage3D(t.id(), 1, format, size.x, size.y, layers);
            glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
            return t;
        };
        bucketDepths_ = array(GL_RGBA32F, targets);
        colors_ = array(rgbaFloatFormat(settings_.precision), colorSlotsPerBucket() * buckets);
        captureFbo_ = gl::Framebuffer::create();
        std::vector<GLenum> drawBuffers;
        for (int i = 0; i < targets; ++i) {
            glNamedFramebufferTextureLayer(captureFbo_.id(), GLenum(GL_COLOR_ATTACHMENT0 + i), bucketDepths_.id(), 0, i);
            drawBuffers.push_back(GLenum(GL_COLOR_ATTACHMENT0 + i));
        }
        glNamedFramebufferDrawBuffers(captureFbo_.id(), GLsizei(drawBuffers.size()), drawBuffers.data());
    }

    void setBucketUniforms(const FrameContext& frame, GLuint program, int buckets) {
        glProgramUniform1i(program, glGetUniformLocation(program, "uBuckets"), buckets);
        glProgramUniform1f(program, glGetUniformLocation(program, "uDepthA"), frame.projection[2][2]);
        glProgramUniform1f(program, glGetUniformLocation(program, "uDepthB"), frame.projection[3][2]);
    }

    void capture(const FrameContext& frame) {
        gl::ScopedPass pass(frame.timer, "bun capture");
        const float neutral[4] = {-2, -2, -2, -2};
        glClearTexImage(bucketDepths_.id(), 0, GL_RGBA, GL_FLOAT, neutral);
        glNamedFramebufferTexture(captureFbo_.id(), GL_DEPTH_ATTACHMENT, frame.targets.depth(), 0);
        glBindFramebuffer(GL_FRAMEBUFFER, captureFbo_.id());
        setTransparentDepthState(frame);
        glEnable(GL_BLEND);
        glBlendEquation(GL_MAX);
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
        glBindTextureUnit(gpu::BIND_PEEL_PREVIOUS, range_.texture());
        stats_.objectDraws += drawTransparent(frame, captureProgram_, frame.transparentOrder);
        glBlendEquation(GL_FUNC_ADD);
        glDisable(GL_BLEND);
        ++stats_.passes;
    }

    void color(const FrameContext& frame) {
        gl::ScopedPass pass(frame.timer, "bun colour");
        glBindFramebuffer(GL_FRAMEBUFFER, frame.targets.outputFramebuffer());
        setTransparentDepthState(frame);
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glBindTextureUnit(gpu::BIND_PEEL_PREVIOUS, range_.texture());
        glBindTextureUnit(gpu::BIND_PEEL_LAYER, bucketDepths_.id());
        glBindImageTexture(gpu::BIND_BUCKET_COLORS, colors_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY,
                           rgbaFloatFormat(settings_.precision));
        stats_.objectDraws += drawTransparent(frame, colorProgram(), frame.transparentOrder);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        ++stats_.passes;
    }

    void composite(const FrameContext& frame, int buckets) {
        gl::ScopedPass pass(frame.timer, "bun composite");
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        glBindFramebuffer(GL_FRAMEBUFFER, frame.targets.outputFramebuffer());
        glDisable(GL_BLEND);
        GLuint p = programs_->composite.id();
        glProgramUniform1i(p, glGetUniformLocation(p, "uBuckets"), buckets);
        glBindTextureUnit(gpu::BIND_OPAQUE_COLOR, frame.targets.opaqueColor());
        glBindTextureUnit(gpu::BIND_PEEL_LAYER, bucketDepths_.id());
        glBindTextureUnit(gpu::BIND_PEEL_ACCUM, colors_.id());
        TransparentAreaScissor scissor(frame);  // the output holds the opaque colour elsewhere
        drawFullscreen(frame, p);
        ++stats_.passes;
    }

    const SceneProgram& colorProgram() const {
        return isHalf(settings_.precision) ? programs_->color16 : programs_->color32;
    }

    struct Programs {
        SceneProgram color16, color32;  // by the colours' precision
        gl::Program composite;
    };
    int allocatedPrecision_ = 0;
    ColorModel model_ = ColorModel::Scalar;  // the colour slots'
    SceneProgram captureProgram_;
    ProgramsPerColorModel<Programs> programs_;  // oit/color_model.hpp
    gl::Buffer counters_;
    glm::ivec2 size_{0, 0};
    int allocatedBuckets_ = 0;
    gl::Texture bucketDepths_, colors_;
    gl::Framebuffer captureFbo_;
    BucketRange range_;
};

}  // namespace
}  // namespace strata::peeling

namespace strata {

TechniqueEntry bunEntry() {
    TechniqueInfo info{"bun", "peeling", false, false, "4 (range + capture + colour + composite)",
                       "w*h*(8 + 16*ceil(B/2) + 16*B) B at precision=16: range, bucket depths, two RGBA16F colours "
                       "per bucket; w*h*(8 + 16*ceil(B/2) + 32*B) B at 32 (RGBA32F colours); twice the colours in a scene "
                       "with coloured filters",
                       "uniform bucket peeling: B depth buckets keep their nearest and farthest fragment in one pass"};
    info.rgbTransmittance = true;
    return techniqueEntry<peeling::BucketPeeling>(info);
}

}  // namespace strata
