// FAB: fixed-size per-pixel arrays (FreePipe's A-buffer in OpenGL). One geometry pass stores
// up to K fragments per pixel; a full-screen pass sorts and composites them.
#include "oit/buffers/buffer_entries.hpp"
#include "oit/buffers/buffer_support.hpp"

#include "common/bindings.h"
#include "gl/shader_program.hpp"
#include "oit/draw_transparent.hpp"

namespace strata {
namespace {

using namespace buffers;

struct FabSettings {
    int capacity = 8;
    bool tail = false;
    int tailPrecision = 32;
    static const SettingsSchema<FabSettings>& schema() {
        static const SettingsSchema<FabSettings> s{
            integerSetting(&FabSettings::capacity, "capacity", 1, 1024, SettingChange::Reallocate,
                           "entries per pixel (K); fragments past the first K to arrive overflow"),
            tailSetting(&FabSettings::tail),
            tailPrecisionSetting(&FabSettings::tailPrecision),
        };
        return s;
    }
};

class Fab final : public TechniqueWithSettings<FabSettings> {
public:
    using TechniqueWithSettings::TechniqueWithSettings;

    void render(const FrameContext& frame) override {
        if (!storeProgram_.program) {
            storeProgram_ = buildSceneProgram("oit/buffers/fab_store.frag.glsl");
            resolveProgram_ = gl::buildProgram({"common/fullscreen.vert.glsl", "oit/buffers/resolve_array.frag.glsl"},
                                               {{"LAYOUT_FAB", ""}});
        }
        const auto k = std::uint64_t(settings_.capacity);
        const auto pixels = std::uint64_t(frame.size.x) * frame.size.y;
        const bool tail = settings_.tail;
        tailTargets_.setPrecision(settings_.tailPrecision);
        if (frame.size != countsSize_) {
            counts_ = gl::createTexture2D(GL_R32UI, frame.size.x, frame.size.y);
            countsSize_ = frame.size;
        }
        if (entriesSize_ != pixels * k) {
            gl::allocateBuffer(entries_, pixels * k * kEntryBytes, GL_DYNAMIC_COPY, "fab entries");
            entriesSize_ = pixels * k;
        }
        stats_ = {};
        {
            gl::ScopedPass pass(frame.timer, "fab store");
            GLuint zero = 0;
            glClearTexImage(counts_.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
            counters_.reset();
            counters_.bind();
            tailTargets_.bindForStore(frame, tail, true);
            setTransparentDepthState(frame);
            glBindImageTexture(gpu::BIND_PIXEL_COUNTS, counts_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BIND_ENTRIES, entries_.id());
            setUniforms(storeProgram_.id(), frame);
            stats_.objectDraws += drawTransparent(frame, storeProgram_, frame.transparentOrder);
            TailTargets::endStore();
            storeBarrier();
            ++stats_.passes;
        }
        {
            gl::ScopedPass pass(frame.timer, "fab resolve");
            glBindFramebuffer(GL_FRAMEBUFFER, frame.targets.outputFramebuffer());
            glBindImageTexture(gpu::BIND_PIXEL_COUNTS, counts_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BIND_ENTRIES, entries_.id());
            glBindTextureUnit(gpu::BIND_OPAQUE_COLOR, frame.targets.opaqueColor());
            tailTargets_.bindForResolve(frame, tail);
            setUniforms(resolveProgram_.id(), frame);
            glProgramUniform1i(resolveProgram_.id(), glGetUniformLocation(resolveProgram_.id(), "uTail"), tail);
            setDepthOrderUniforms(frame, resolveProgram_.id());
            drawFullscreen(frame, resolveProgram_.id());
            ++stats_.passes;
        }
        auto c = counters_.read();  // [0] stored, [1] overflowed (sum over pixels of count - K)
        stats_.fragmentsCaptured = c[0];
        stats_.overflowed = c[1] > 0;
        (tail ? stats_.fragmentsTail : stats_.fragmentsDropped) = c[1];
        // The Table-1 model: K entries per pixel plus the per-pixel counter.
        stats_.bytes = pixels * k * kEntryBytes + pixels * 4 + kCounterBytes + tailTargets_.bytes(tail, frame.size);
    }

private:
    void setUniforms(GLuint program, const FrameContext& frame) const {
        glProgramUniform1ui(program, glGetUniformLocation(program, "uWidth"), GLuint(frame.size.x));
        glProgramUniform1ui(program, glGetUniformLocation(program, "uCapacity"), GLuint(settings_.capacity));
    }

    SceneProgram storeProgram_;
    gl::Program resolveProgram_;
    gl::Texture counts_;
    glm::ivec2 countsSize_{0, 0};
    gl::Buffer entries_;
    std::uint64_t entriesSize_ = 0;
    Counters counters_;
    TailTargets tailTargets_;
};

}  // namespace

TechniqueEntry fabEntry() {
    TechniqueInfo info{"fab", "buffer", false, true, "2",
                       "w*h*K*20 entries + w*h*4 counters + 16 (+ w*h*20 with tail=1, w*h*10 with tail=1 precision=16)",
                       "fixed-size per-pixel arrays of K entries with an atomic per-pixel counter (r32ui image); keeps "
                       "the first K fragments to arrive, counts the rest (dropped, or blended approximately with tail=1); "
                       "resolve sorts by (depth, object, primitive)"};
    return techniqueEntry<Fab>(info);
}

}  // namespace strata
