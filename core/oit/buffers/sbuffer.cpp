// S-buffer (Vasilakis & Fudos 2012): count each pixel's fragments, prefix-sum the counts into
// variable contiguous regions, store, then sort and composite each region. Memory is sized
// exactly from the count, so nothing overflows unless the total exceeds the largest storage
// block the device allows (then the excess is counted as dropped).
#include "oit/buffers/buffer_entries.hpp"
#include "oit/buffers/buffer_support.hpp"
#include "oit/buffers/prefix_sum.hpp"

#include "gl/shader_program.hpp"
#include "oit/draw_transparent.hpp"
#include "render/bindings.hpp"

#include <algorithm>

namespace strata {
namespace {

using namespace buffers;

class SBuffer final : public Technique {
public:
    explicit SBuffer(TechniqueInfo info) : info_(std::move(info)) {}
    const TechniqueInfo& info() const override { return info_; }

    void render(const FrameContext& frame) override {
        if (!storeProgram_.program) {
            storeProgram_ = buildSceneProgram("oit/buffers/sbuffer_store.frag.glsl");
            resolveProgram_ = gl::buildProgram({"common/fullscreen.vert.glsl", "oit/buffers/resolve_array.frag.glsl"},
                                               {{"LAYOUT_SBUFFER", ""}});
        }
        const auto pixels = std::uint64_t(frame.size.x) * frame.size.y;
        if (offsetsSize_ != pixels) {
            gl::allocateBuffer(offsets_, pixels * 4, GL_DYNAMIC_COPY, "sbuffer offsets");
            offsetsSize_ = pixels;
        }
        stats_ = {};
        const GLuint program = storeProgram_.id();
        glProgramUniform1ui(program, glGetUniformLocation(program, "uWidth"), GLuint(frame.size.x));
        const GLint passLocation = glGetUniformLocation(program, "uPass");
        {
            gl::ScopedPass pass(frame.timer, "sbuffer count");
            GLuint zero = 0;
            glClearNamedBufferData(offsets_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
            counters_.reset();
            counters_.bind();
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindPixelOffsets, offsets_.id());
            glBindFramebuffer(GL_FRAMEBUFFER, frame.targets.outputFramebuffer());
            glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
            setTransparentDepthState(frame);
            glProgramUniform1i(program, passLocation, 0);
            stats_.objectDraws += drawTransparent(frame, storeProgram_, frame.transparentOrder);
            storeBarrier();
            ++stats_.passes;
        }
        std::uint64_t total = 0;
        {
            gl::ScopedPass pass(frame.timer, "sbuffer prefix sum");
            total = scan_.scan(offsets_.id(), pixels);
        }
        // Exactly the counted fragments, bounded by the largest block the device allows.
        GLint64 limit = 0;
        glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &limit);
        const std::uint64_t capacity = std::min<std::uint64_t>(total, std::uint64_t(limit) / kEntryBytes);
        if (entriesSize_ != capacity || !entries_) {
            gl::allocateBuffer(entries_, std::max<std::uint64_t>(capacity, 1) * kEntryBytes, GL_DYNAMIC_COPY,
                               "sbuffer entries");
            entriesSize_ = capacity;
        }
        {
            gl::ScopedPass pass(frame.timer, "sbuffer store");
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindPixelOffsets, offsets_.id());
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindEntries, entries_.id());
            counters_.bind();
            glBindFramebuffer(GL_FRAMEBUFFER, frame.targets.outputFramebuffer());
            glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
            setTransparentDepthState(frame);
            glProgramUniform1ui(program, glGetUniformLocation(program, "uCapacity"), GLuint(capacity));
            glProgramUniform1i(program, passLocation, 1);
            stats_.objectDraws += drawTransparent(frame, storeProgram_, frame.transparentOrder);
            glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
            storeBarrier();
            ++stats_.passes;
        }
        {
            gl::ScopedPass pass(frame.timer, "sbuffer resolve");
            glBindFramebuffer(GL_FRAMEBUFFER, frame.targets.outputFramebuffer());
            glBindTextureUnit(bindings::kOpaqueColor, frame.targets.opaqueColor());
            tailTargets_.bindForResolve(frame, false);
            const GLuint resolve = resolveProgram_.id();
            glProgramUniform1ui(resolve, glGetUniformLocation(resolve, "uWidth"), GLuint(frame.size.x));
            glProgramUniform1i(resolve, glGetUniformLocation(resolve, "uTail"), 0);
            setDepthOrderUniforms(frame, resolve);
            drawFullscreen(frame, resolve);
            ++stats_.passes;
        }
        const std::uint64_t dropped = counters_.read()[0];
        stats_.fragmentsCaptured = total - dropped;
        stats_.fragmentsDropped = dropped;
        stats_.overflowed = dropped > 0;
        stats_.bytes = pixels * 4 + std::max<std::uint64_t>(capacity, 1) * kEntryBytes + scan_.bytes() + kCounterBytes;
    }

private:
    TechniqueInfo info_;
    SceneProgram storeProgram_;
    gl::Program resolveProgram_;
    gl::Buffer offsets_, entries_;
    std::uint64_t offsetsSize_ = 0, entriesSize_ = 0;
    PrefixSum scan_;
    Counters counters_;
    TailTargets tailTargets_;
};

}  // namespace

TechniqueEntry sbufferEntry() {
    TechniqueInfo info{"sbuffer", "buffer", true, true, "3 (count, store, resolve) + prefix-sum dispatches",
                       "w*h*4 offsets + 20 B per fragment (sized exactly from the count) + prefix-sum block totals + 16",
                       "S-buffer: counting pass, GPU prefix sum over pixels (work-efficient block scan), variable "
                       "contiguous region per pixel, store, resolve sorting by (depth, object, primitive)"};
    return {info, [info] { return std::make_unique<SBuffer>(info); }};
}

}  // namespace strata
