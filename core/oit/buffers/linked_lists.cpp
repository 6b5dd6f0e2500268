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

class LinkedLists final : public Technique {
public:
    explicit LinkedLists(TechniqueInfo info) : info_(std::move(info)) {}
    const TechniqueInfo& info() const override { return info_; }

    std::vector<Parameter> parameters() override {
        return {capacityParameter(&capacity_, 1024, "node pool size as nodes per pixel on average (pool = w*h*capacity)"),
                tailParameter(&tail_), tailPrecisionParameter(&tailPrecision_)};
    }

    void render(const FrameContext& frame) override {
        if (!storeProgram_.program) {
            storeProgram_ = buildSceneProgram("oit/buffers/ll_store.frag.glsl");
            resolveProgram_ = gl::buildProgram({"common/fullscreen.vert.glsl", "oit/abuffer_resolve.frag.glsl"},
                                              {{"LIST_TAIL", ""}});
        }
        const auto pixels = std::uint64_t(frame.size.x) * frame.size.y;
        const std::uint64_t pool = pixels * std::uint64_t(capacity_);
        const bool tail = tail_ != 0;
        tailTargets_.setPrecision(tailPrecision_);
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
    TechniqueInfo info_;
    SceneProgram storeProgram_;
    gl::Program resolveProgram_;
    gl::Texture heads_;
    glm::ivec2 headsSize_{0, 0};
    gl::Buffer nodes_;
    std::uint64_t poolNodes_ = 0;
    Counters counters_;
    TailTargets tailTargets_;
    double capacity_ = 8;
    double tail_ = 0;
    double tailPrecision_ = 32;
};

}  // namespace

TechniqueEntry llEntry() {
    TechniqueInfo info{"ll", "buffer", false, true, "2",
                       "w*h*capacity*24 node pool + w*h*4 heads + 16 (+ w*h*20 with tail=1, w*h*10 with tail=1 precision=16)",
                       "per-pixel linked lists: head-pointer image, one global atomic counter, a fixed node pool "
                       "(capacity nodes per pixel on average, never grown); overflow counted and dropped or blended "
                       "approximately (tail=1); resolve sorts by (depth, object, primitive)"};
    return {info, [info] { return std::make_unique<LinkedLists>(info); }};
}

}  // namespace strata
