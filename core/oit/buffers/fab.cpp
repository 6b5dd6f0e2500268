// FAB: fixed-size per-pixel arrays (FreePipe's A-buffer in OpenGL). One geometry pass stores
// up to K fragments per pixel; a full-screen pass sorts and composites them.
#include "oit/buffers/bounded_buffer.hpp"
#include "oit/technique.hpp"

#include "common/bindings.h"

namespace strata {
namespace {

using namespace buffers;

struct FabCapacity {
    static constexpr int kMax = 1024;
    static constexpr const char* kHelp = "entries per pixel (K); fragments past the first K to arrive overflow";
};

class Fab final : public BoundedBuffer<FabCapacity> {
public:
    using BoundedBuffer::BoundedBuffer;

private:
    Shaders shaders() const override {
        return {"oit/buffers/fab_store.frag.glsl",
                {"common/fullscreen.vert.glsl", "oit/buffers/resolve_array.frag.glsl"},
                {{"LAYOUT_FAB", ""}}};
    }

    void allocate(const FrameContext& frame, int capacity) override {
        if (frame.size != countsSize_) {
            counts_ = gl::createTexture2D(GL_R32UI, frame.size.x, frame.size.y);
            countsSize_ = frame.size;
        }
        const std::uint64_t entries = pixelCount(frame) * std::uint64_t(capacity);
        if (entriesSize_ != entries) {
            gl::allocateBuffer(entries_, entries * kEntryBytes, GL_DYNAMIC_COPY, "fab entries");
            entriesSize_ = entries;
        }
    }

    void clear() override {
        GLuint zero = 0;
        glClearTexImage(counts_.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    }

    void bindStorage() override {
        glBindImageTexture(gpu::BIND_PIXEL_COUNTS, counts_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BIND_ENTRIES, entries_.id());
    }

    void setUniforms(GLuint program, const FrameContext& frame, int capacity) const override {
        glProgramUniform1ui(program, glGetUniformLocation(program, "uWidth"), GLuint(frame.size.x));
        glProgramUniform1ui(program, glGetUniformLocation(program, "uCapacity"), GLuint(capacity));
    }

    // [0] stored, [1] overflowed (sum over pixels of count - K).
    StoreCounts counts(const std::array<std::uint32_t, 4>& c, const FrameContext&, int) const override {
        return {c[0], c[1]};
    }

    // The Table-1 model: K entries per pixel plus the per-pixel counter.
    std::uint64_t storageBytes(const FrameContext& frame, int capacity) const override {
        return pixelCount(frame) * (std::uint64_t(capacity) * kEntryBytes + 4) + kCounterBytes;
    }

    gl::Texture counts_;
    glm::ivec2 countsSize_{0, 0};
    gl::Buffer entries_;
    std::uint64_t entriesSize_ = 0;
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
