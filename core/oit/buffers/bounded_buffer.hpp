#pragma once
// The skeleton of the bounded buffers (fab, kbuffer, ll): a fixed capacity, store passes over the
// transparent geometry that count what they keep and what overflows, an optional tail that blends
// the overflow approximately, then one full-screen pass that sorts each pixel's fragments and
// composites them (ordered_composite.glsl). A technique supplies its capacity's meaning, its
// storage, its shaders and how its counters read; the frame is run here once for all three.
#include "oit/buffers/buffer_support.hpp"

#include "gl/shader_program.hpp"
#include "oit/color_model.hpp"
#include "oit/draw_transparent.hpp"

#include <array>
#include <optional>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>


namespace strata::buffers {

// `Capacity` names what the capacity counts: static constexpr int kMax; const char* kHelp.
template <class Capacity>
struct BoundedSettings {
    int capacity = 8;
    bool tail = false;
    int tailPrecision = 32;

    static const SettingsSchema<BoundedSettings>& schema() {
        static const SettingsSchema<BoundedSettings> s{
            integerSetting(&BoundedSettings::capacity, "capacity", 1, Capacity::kMax, SettingChange::Reallocate,
                           Capacity::kHelp),
            tailSetting(&BoundedSettings::tail),
            tailPrecisionSetting(&BoundedSettings::tailPrecision),
        };
        return s;
    }
};

// A per-pixel r32ui image (fab's counts, ll's heads), reallocated with the frame's size,
// cleared to zero before each store.
class PixelImage {
public:
    void ensure(glm::ivec2 size);
    void clear() const;
    void bind(unsigned unit) const;  // read-write image unit

private:
    gl::Texture texture_;
    glm::ivec2 size_{0, 0};
};

// A storage buffer of `count` elements of `elementBytes`, reallocated when the count changes.
class SizedBuffer {
public:
    // Returns whether it (re)allocated: views of the old buffer are stale.
    bool ensure(std::uint64_t count, std::uint64_t elementBytes, const char* label);
    GLuint id() const { return buffer_.id(); }

private:
    gl::Buffer buffer_;
    std::uint64_t count_ = 0;
};

// What the store passes kept and what did not fit, read from the counters.
struct StoreCounts {
    std::uint64_t captured = 0;
    std::uint64_t overflow = 0;
};

// The frame of a bounded buffer, independent of its settings type.
class BoundedBufferFrame {
public:
    virtual ~BoundedBufferFrame() = default;

protected:
    struct Shaders {
        std::string store;                         // scene fragment shader
        std::vector<std::string> resolve;          // full-screen program
        gl::Defines resolveDefines;
        gl::Defines storeDefines = {};
        // The resolve has a second build with NODE_TEXELS (oit/node_fetch.glsl: the node pool
        // read through a buffer texture), used on frames whose pool fits one (nodeTexelsFit).
        bool nodeTexels = false;
    };
    struct Bounds {
        int capacity;
        bool tail;
        int tailPrecision;
    };

    virtual Shaders shaders() const = 0;
    // A lighter program pair for a frame that needs less than shaders() gives (ll-volume on a
    // scene without volume objects draws as ll); none by default. Built on first use.
    virtual std::optional<Shaders> lighterShaders(const FrameContext& /*frame*/) const { return std::nullopt; }
    // (Re)allocates for the frame's size and the capacity; called every frame.
    virtual void allocate(const FrameContext& frame, int capacity) = 0;
    // Clears what the store passes fill (called once before them).
    virtual void clear() = 0;
    // Binds the images and buffers both the store and the resolve read or write.
    virtual void bindStorage() = 0;
    // Uniforms of both programs (the frame's width, the capacity).
    virtual void setUniforms(GLuint program, const FrameContext& frame, int capacity) const = 0;
    virtual StoreCounts counts(const std::array<std::uint32_t, 4>& counters, const FrameContext& frame,
                               int capacity) const = 0;
    // The memory the technique holds (Table 1's model), without the tail.
    virtual std::uint64_t storageBytes(const FrameContext& frame, int capacity) const = 0;
    // Store passes: one by default; the name is "<id> store".
    virtual int storePasses() const { return 1; }
    virtual std::string storePassName(int pass) const;
    // Called before each store pass (a per-pass uniform); whether the pass writes the tail.
    virtual void beginStorePass(int /*pass*/) {}
    virtual bool storePassWritesTail(int /*pass*/) const { return true; }
    // Called with the resolve program bound to its inputs, before it draws: binds what else it
    // reads and returns the framebuffer it draws into (the frame's output by default).
    virtual GLuint prepareResolve(const FrameContext& frame, GLuint /*program*/) {
        return frame.targets.outputFramebuffer();
    }
    // After allocate: whether this frame's node pool has its buffer-texture view, bound by
    // bindStorage at gpu::BIND_NODE_TEXELS (Shaders::nodeTexels).
    virtual bool nodeTexelsFit() const { return false; }
    // Called after the resolve with the frame's statistics filled in from the counters.
    virtual void finishResolve(TechniqueStats& /*stats*/) {}

    static std::uint64_t pixelCount(const FrameContext& frame) { return std::uint64_t(frame.size.x) * frame.size.y; }

    void renderFrame(const FrameContext& frame, const std::string& id, const Bounds& bounds, TechniqueStats& stats);

    // The frame's store program (renderFrame picks it; beginStorePass sets per-pass uniforms on it).
    const SceneProgram& storeProgram() const { return current_->store; }

private:
    struct Programs {
        SceneProgram store;
        gl::Program resolve;
        gl::Program resolveTexels;  // Shaders::nodeTexels: built on the first frame that uses it
    };
    // Built on first use, by [lighter][ColorModel]: the volumetric builds stay scalar (their
    // resolve reads the scalar layout), every other build composites coloured filters exactly
    // in a scene that has them.
    Programs programs_[2][kColorModels];
    Programs* current_ = nullptr;
    std::string id_;
    Counters counters_;
    TailTargets tailTargets_;
};

template <class Capacity>
class BoundedBuffer : public TechniqueWithSettings<BoundedSettings<Capacity>>, protected BoundedBufferFrame {
public:
    using TechniqueWithSettings<BoundedSettings<Capacity>>::TechniqueWithSettings;

    void render(const FrameContext& frame) final {
        const auto& s = this->settings_;
        renderFrame(frame, this->info().id, {s.capacity, s.tail, s.tailPrecision}, this->stats_);
    }
};

}  // namespace strata::buffers
