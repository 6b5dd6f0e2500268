// K-buffer: the K nearest fragments per pixel in bounded memory. Without fragment-shader
// interlock (llvmpipe has none) the read-modify-write of the K-buffer is done with 32-bit
// atomics instead of a lock: a depth-key insertion pass (a chain of atomicMax, lock-free, cannot
// hang), then an attribute pass in which each kept fragment claims its slot by atomicCompSwap;
// see shaders/oit/buffers/kbuffer_store.frag.glsl. Then the shared sort-and-composite resolve.
#include "oit/buffers/bounded_buffer.hpp"
#include "oit/technique.hpp"

#include "common/bindings.h"

namespace strata {
namespace {

using namespace buffers;

struct KBufferCapacity {
    // Bounded like the hardware k-buffer: each fragment walks the K slots in its insertion.
    static constexpr int kMax = 64;
    static constexpr const char* kHelp = "slots per pixel (K): the K nearest fragments are kept";
};

class KBuffer final : public BoundedBuffer<KBufferCapacity> {
public:
    using BoundedBuffer::BoundedBuffer;

private:
    // Per slot: the 4-byte depth key and the attributes.
    static constexpr std::uint64_t kBytesPerSlot = 4 + kEntryBytes;

    Shaders shaders() const override {
        return {"oit/buffers/kbuffer_store.frag.glsl",
                {"common/fullscreen.vert.glsl", "oit/buffers/resolve_array.frag.glsl"},
                {{"LAYOUT_KBUFFER", ""}}};
    }

    void allocate(const FrameContext& frame, int capacity) override {
        const std::uint64_t slots = pixelCount(frame) * std::uint64_t(capacity);
        keys_.ensure(slots, 4, "kbuffer depth keys");
        entries_.ensure(slots, kEntryBytes, "kbuffer entries");
    }

    void clear() override {
        GLuint zero = 0, unclaimed = 0xFFFFFFFFu;
        glClearNamedBufferData(keys_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
        glClearNamedBufferData(entries_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &unclaimed);
    }

    void bindStorage() override {
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BIND_DEPTH_KEYS, keys_.id());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BIND_ENTRIES, entries_.id());
    }

    void setUniforms(GLuint program, const FrameContext& frame, int capacity) const override {
        glProgramUniform1ui(program, glGetUniformLocation(program, "uWidth"), GLuint(frame.size.x));
        glProgramUniform1ui(program, glGetUniformLocation(program, "uCapacity"), GLuint(capacity));
    }

    int storePasses() const override { return 2; }
    std::string storePassName(int pass) const override { return pass == 0 ? "kbuffer depth keys" : "kbuffer attributes"; }
    void beginStorePass(int pass) override {
        const GLuint program = storeProgram().id();
        glProgramUniform1i(program, glGetUniformLocation(program, "uPass"), pass);
    }
    // The tail is written in the attribute pass only, where a fragment knows it was not kept.
    bool storePassWritesTail(int pass) const override { return pass == 1; }

    // [0] inserted, [1] pushed past the K-th slot.
    StoreCounts counts(const std::array<std::uint32_t, 4>& c, const FrameContext&, int) const override {
        return {c[0] - c[1], c[1]};
    }

    std::uint64_t storageBytes(const FrameContext& frame, int capacity) const override {
        return pixelCount(frame) * std::uint64_t(capacity) * kBytesPerSlot + kCounterBytes;
    }

    SizedBuffer keys_, entries_;
};

}  // namespace

TechniqueEntry kbufferEntry() {
    TechniqueInfo info{"kbuffer", "buffer", false, true, "3 (depth keys, attributes, resolve)",
                       "w*h*K*(4+20) + 16 (+ w*h*20 with tail=1, w*h*10 with tail=1 precision=16)",
                       "k-buffer of the K nearest fragments per pixel, no interlock: lock-free 32-bit atomicMax "
                       "insertion of depth keys, then slots claimed by atomicCompSwap; what does not fit is dropped "
                       "(or blended approximately with tail=1); K bounded (max 64), so not robust"};
    info.rgbTransmittance = true;
    return techniqueEntry<KBuffer>(info);
}

}  // namespace strata
