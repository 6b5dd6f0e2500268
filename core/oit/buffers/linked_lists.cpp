// Per-pixel linked lists with a fixed node pool (Yang et al. 2010). The same structure as the
// abuffer reference, but the pool is a parameter (average nodes per pixel) and never grows:
// what does not fit is counted and dropped, or blended approximately with tail=1.
#include "oit/buffers/buffer_entries.hpp"
#include "oit/buffers/buffer_support.hpp"

#include "common/bindings.h"
#include "gl/shader_program.hpp"
#include "oit/draw_transparent.hpp"

namespace strata {
namespace {

using namespace buffers;

struct LinkedListsSettings {
    int capacity = 8;
    bool tail = false;
    int tailPrecision = 32;
    static const SettingsSchema<LinkedListsSettings>& schema() {
        static const SettingsSchema<LinkedListsSettings> s{
            integerSetting(&LinkedListsSettings::capacity, "capacity", 1, 1024, SettingChange::Reallocate,
                           "node pool size as nodes per pixel on average (pool = w*h*capacity)"),
            tailSetting(&LinkedListsSettings::tail),
            tailPrecisionSetting(&LinkedListsSettings::tailPrecision),
        };
        return s;
    }
};

class LinkedLists final : public TechniqueWithSettings<LinkedListsSettings> {
public:
    using TechniqueWithSettings::TechniqueWithSettings;

    void render(const FrameContext& frame) override {
        if (!storeProgram_.program) {
            storeProgram_ = buildSceneProgram("oit/buffers/ll_store.frag.glsl");
            resolveProgram_ = gl::buildProgram({"common/fullscreen.vert.glsl", "oit/abuffer_resolve.frag.glsl"},
                                              {{"LIST_TAIL", ""}});
        }
        const auto pixels = std::uint64_t(frame.size.x) * frame.size.y;
        const std::uint64_t pool = pixels * std::uint64_t(settings_.capacity);
        const bool tail = settings_.tail;
        tailTargets_.setPrecision(settings_.tailPrecision);
        if (pool > 0xFFFFFFFEull) throw std::runtime_error("ll: node pool of " + std::to_string(pool) + " nodes exceeds 32-bit indices");
        if (frame.size != headsSize_) {
            heads_ = gl::createTexture2D(GL_R32UI, frame.size.x, frame.size.y);
            headsSize_ = frame.size;
        }
        if (poolNodes_ != pool) {
            gl::allocateBuffer(nodes_, pool * kNodeBytes, GL_DYNAMIC_COPY, "ll node pool");
            poolNodes_ = pool;
        }
        stats_ = {};
        {
            gl::ScopedPass pass(frame.timer, "ll store");
            GLuint zero = 0;
            glClearTexImage(heads_.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
            counters_.reset();
            counters_.bind();
            tailTargets_.bindForStore(frame, tail, true);
            setTransparentDepthState(frame);
            glBindImageTexture(gpu::BIND_HEADS, heads_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BIND_NODES, nodes_.id());
            glProgramUniform1ui(storeProgram_.id(), glGetUniformLocation(storeProgram_.id(), "uCapacity"), GLuint(pool));
            stats_.objectDraws += drawTransparent(frame, storeProgram_, frame.transparentOrder);
            TailTargets::endStore();
            storeBarrier();
            ++stats_.passes;
        }
        {
            gl::ScopedPass pass(frame.timer, "ll resolve");
            glBindFramebuffer(GL_FRAMEBUFFER, frame.targets.outputFramebuffer());
            glBindImageTexture(gpu::BIND_HEADS, heads_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BIND_NODES, nodes_.id());
            glBindTextureUnit(gpu::BIND_OPAQUE_COLOR, frame.targets.opaqueColor());
            tailTargets_.bindForResolve(frame, tail);
            glProgramUniform1i(resolveProgram_.id(), glGetUniformLocation(resolveProgram_.id(), "uTail"), tail);
            setDepthOrderUniforms(frame, resolveProgram_.id());
            drawFullscreen(frame, resolveProgram_.id());
            ++stats_.passes;
        }
        // The counter keeps running past the pool: it is the number of fragments that arrived.
        const std::uint64_t arrived = counters_.read()[0];
        const std::uint64_t overflow = arrived > pool ? arrived - pool : 0;
        stats_.fragmentsCaptured = arrived - overflow;
        stats_.overflowed = overflow > 0;
        (tail ? stats_.fragmentsTail : stats_.fragmentsDropped) = overflow;
        stats_.bytes = pool * kNodeBytes + pixels * 4 + kCounterBytes + tailTargets_.bytes(tail, frame.size);
    }

private:
    SceneProgram storeProgram_;
    gl::Program resolveProgram_;
    gl::Texture heads_;
    glm::ivec2 headsSize_{0, 0};
    gl::Buffer nodes_;
    std::uint64_t poolNodes_ = 0;
    Counters counters_;
    TailTargets tailTargets_;
};

}  // namespace

TechniqueEntry llEntry() {
    TechniqueInfo info{"ll", "buffer", false, true, "2",
                       "w*h*capacity*24 node pool + w*h*4 heads + 16 (+ w*h*20 with tail=1, w*h*10 with tail=1 precision=16)",
                       "per-pixel linked lists: head-pointer image, one global atomic counter, a fixed node pool "
                       "(capacity nodes per pixel on average, never grown); overflow counted and dropped or blended "
                       "approximately (tail=1); resolve sorts by (depth, object, primitive)"};
    return techniqueEntry<LinkedLists>(info);
}

}  // namespace strata
