// K-buffer: the K nearest fragments per pixel in bounded memory. Without fragment-shader
// interlock (llvmpipe has none) the read-modify-write of the K-buffer is done with 32-bit
// atomics instead of a lock: a depth-key insertion pass (a chain of atomicMax, lock-free, cannot
// hang), then an attribute pass in which each kept fragment claims its slot by atomicCompSwap;
// see shaders/oit/buffers/kbuffer_store.frag.glsl. Then the shared sort-and-composite resolve.
#include "oit/buffers/buffer_entries.hpp"
#include "oit/buffers/buffer_support.hpp"

#include "common/bindings.h"
#include "gl/shader_program.hpp"
#include "oit/draw_transparent.hpp"

namespace strata {
namespace {

using namespace buffers;

struct KBufferSettings {
    int capacity = 8;
    bool tail = false;
    int tailPrecision = 32;
    static const SettingsSchema<KBufferSettings>& schema() {
        static const SettingsSchema<KBufferSettings> s{
            integerSetting(&KBufferSettings::capacity, "capacity", 1, 64, SettingChange::Reallocate,
                           "slots per pixel (K): the K nearest fragments are kept"),
            tailSetting(&KBufferSettings::tail),
            tailPrecisionSetting(&KBufferSettings::tailPrecision),
        };
        return s;
    }
};

class KBuffer final : public TechniqueWithSettings<KBufferSettings> {
public:
    // Per entry: the 4-byte depth key and the 20-byte attributes.
    static constexpr std::uint64_t kBytesPerSlot = 4 + kEntryBytes;

    using TechniqueWithSettings::TechniqueWithSettings;

    void render(const FrameContext& frame) override {
        if (!storeProgram_.program) {
            storeProgram_ = buildSceneProgram("oit/buffers/kbuffer_store.frag.glsl");
            resolveProgram_ = gl::buildProgram({"common/fullscreen.vert.glsl", "oit/buffers/resolve_array.frag.glsl"},
                                               {{"LAYOUT_KBUFFER", ""}});
        }
        const auto k = std::uint64_t(settings_.capacity);
        const auto pixels = std::uint64_t(frame.size.x) * frame.size.y;
        const bool tail = settings_.tail;
        tailTargets_.setPrecision(settings_.tailPrecision);
        if (slots_ != pixels * k) {
            gl::allocateBuffer(keys_, pixels * k * 4, GL_DYNAMIC_COPY, "kbuffer depth keys");
            gl::allocateBuffer(entries_, pixels * k * kEntryBytes, GL_DYNAMIC_COPY, "kbuffer entries");
            slots_ = pixels * k;
        }
        stats_ = {};
        GLuint zero = 0, unclaimed = 0xFFFFFFFFu;
        glClearNamedBufferData(keys_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
        glClearNamedBufferData(entries_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &unclaimed);
        counters_.reset();
        counters_.bind();
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BIND_DEPTH_KEYS, keys_.id());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BIND_ENTRIES, entries_.id());
        setUniforms(storeProgram_.id(), frame);
        const GLint passLocation = glGetUniformLocation(storeProgram_.id(), "uPass");
        for (int p = 0; p < 2; ++p) {
            gl::ScopedPass pass(frame.timer, p == 0 ? "kbuffer depth keys" : "kbuffer attributes");
            // The tail is written in the attribute pass only, where a fragment knows it was not kept.
            tailTargets_.bindForStore(frame, tail && p == 1, true);
            setTransparentDepthState(frame);
            glProgramUniform1i(storeProgram_.id(), passLocation, p);
            stats_.objectDraws += drawTransparent(frame, storeProgram_, frame.transparentOrder);
            TailTargets::endStore();
            storeBarrier();
            ++stats_.passes;
        }
        {
            gl::ScopedPass pass(frame.timer, "kbuffer resolve");
            glBindFramebuffer(GL_FRAMEBUFFER, frame.targets.outputFramebuffer());
            glBindTextureUnit(gpu::BIND_OPAQUE_COLOR, frame.targets.opaqueColor());
            tailTargets_.bindForResolve(frame, tail);
            setUniforms(resolveProgram_.id(), frame);
            glProgramUniform1i(resolveProgram_.id(), glGetUniformLocation(resolveProgram_.id(), "uTail"), tail);
            setDepthOrderUniforms(frame, resolveProgram_.id());
            drawFullscreen(frame, resolveProgram_.id());
            ++stats_.passes;
        }
        auto c = counters_.read();  // [0] inserted, [1] pushed past the K-th slot
        stats_.fragmentsCaptured = c[0] - c[1];
        stats_.overflowed = c[1] > 0;
        (tail ? stats_.fragmentsTail : stats_.fragmentsDropped) = c[1];
        stats_.bytes = pixels * k * kBytesPerSlot + kCounterBytes + tailTargets_.bytes(tail, frame.size);
    }

private:
    void setUniforms(GLuint program, const FrameContext& frame) const {
        glProgramUniform1ui(program, glGetUniformLocation(program, "uWidth"), GLuint(frame.size.x));
        glProgramUniform1ui(program, glGetUniformLocation(program, "uCapacity"), GLuint(settings_.capacity));
    }

    SceneProgram storeProgram_;
    gl::Program resolveProgram_;
    gl::Buffer keys_, entries_;
    std::uint64_t slots_ = 0;
    Counters counters_;
    TailTargets tailTargets_;
};

}  // namespace

TechniqueEntry kbufferEntry() {
    TechniqueInfo info{"kbuffer", "buffer", false, true, "3 (depth keys, attributes, resolve)",
                       "w*h*K*(4+20) + 16 (+ w*h*20 with tail=1, w*h*10 with tail=1 precision=16)",
                       "k-buffer of the K nearest fragments per pixel, no interlock: lock-free 32-bit atomicMax "
                       "insertion of depth keys, then slots claimed by atomicCompSwap; what does not fit is dropped "
                       "(or blended approximately with tail=1); K bounded (max 64), so not robust"};
    return techniqueEntry<KBuffer>(info);
}

}  // namespace strata
