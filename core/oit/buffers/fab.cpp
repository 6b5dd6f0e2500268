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
        counts_.ensure(frame.size);
        entries_.ensure(pixelCount(frame) * std::uint64_t(capacity), kEntryBytes, "fab entries");
    }

    void clear() override { counts_.clear(); }

    void bindStorage() override {
        counts_.bind(gpu::BIND_PIXEL_COUNTS);
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

    PixelImage counts_;
    SizedBuffer entries_;
};

}  // namespace

TechniqueEntry fabEntry() {
    TechniqueInfo info{"fab", "buffer", false, true, "2",
                       "w*h*K*20 entries + w*h*4 counters + 16 (+ w*h*20 with tail=1, w*h*10 with tail=1 precision=16)",
                       "fixed-size per-pixel arrays of K entries with an atomic per-pixel counter (r32ui image); keeps "
                       "the first K fragments to arrive, counts the rest (dropped, or blended approximately with tail=1); "
                       "resolve sorts by (depth, object, primitive)"};
    info.rgbTransmittance = true;
    return techniqueEntry<Fab>(info);
}

}  // namespace strata
