#pragma once
// What the buffer family (fab, kbuffer, ll, sbuffer) shares on the host: the atomic counters
// each store pass reports through, and the optional "tail" targets that blend overflowed
// fragments approximately instead of dropping them. Binding points and the entry layout are
// shared with the shaders in shaders/oit/buffers/buffer_bindings.h.
#include "gl/objects.hpp"
#include "oit/abuffer_node.h"
#include "oit/buffers/buffer_bindings.h"
#include "oit/technique.hpp"

#include <array>
#include <cstddef>
#include <cstdint>

namespace strata::buffers {

constexpr std::uint64_t kEntryBytes = sizeof(gpu::FragmentEntry);
constexpr std::uint64_t kNodeBytes = sizeof(gpu::FragmentNode);  // ll's fixed pool

// Four atomic counters (uint) a store pass increments; meaning per technique. The shaders
// address them by byte offset (0, 4, 8, 12) at gpu::BIND_COUNTERS.
constexpr std::size_t kCounterSlots = 4;
constexpr std::uint64_t kCounterBytes = kCounterSlots * sizeof(std::uint32_t);

class Counters {
public:
    void reset();                    // creates on first use, zeroes
    void bind() const;               // GL_ATOMIC_COUNTER_BUFFER at gpu::BIND_COUNTERS
    std::array<std::uint32_t, kCounterSlots> read() const;  // after the pass and a barrier

private:
    gl::Buffer buffer_;
};

// Accumulation targets of the tail: sum(a*c, a) in RGBA and prod(1-a) in R, float at the
// tail's precision (32: RGBA32F + R32F, 20 bytes per pixel; 16: RGBA16F + R16F, 10), sharing
// the opaque depth so the store pass depth-tests as usual.
class TailTargets {
public:
    // 16 or 32 (tailPrecisionParameter); takes effect at the next bind.
    void setPrecision(int bits) { bits_ = bits; }
    std::uint64_t bytesPerPixel() const;
    // Binds a framebuffer for a store pass: the tail targets (cleared on `clear`) when `enabled`,
    // else the output framebuffer with colour writes masked. Sets blending for the tail.
    void bindForStore(const FrameContext& frame, bool enabled, bool clear);
    // Restores colour writes and blending after the store pass.
    static void endStore();
    // Binds the tail textures for the resolve (also when disabled: the shader skips them).
    void bindForResolve(const FrameContext& frame, bool enabled);
    std::uint64_t bytes(bool enabled, glm::ivec2 size) const {
        return enabled ? bytesPerPixel() * std::uint64_t(size.x) * size.y : 0;
    }

private:
    void ensure(const FrameContext& frame);
    gl::Texture accum_, reveal_;
    gl::Framebuffer fbo_;
    glm::ivec2 size_{0, 0};
    int bits_ = 32, allocatedBits_ = 0;
};

// The knobs every bounded buffer offers besides its capacity.
template <class S>
typename SettingsSchema<S>::Field tailSetting(bool S::*member) {
    return flagSetting(member, "tail", SettingChange::Reallocate,
                       "blend what overflows approximately (one weighted-average layer behind the kept ones) instead of "
                       "dropping it");
}

template <class S>
typename SettingsSchema<S>::Field tailPrecisionSetting(int S::*member) {
    return precisionSetting(member, "tail's accumulation targets (with tail on)");
}

// Barrier after a store pass that wrote images, buffers and counters.
void storeBarrier();

}  // namespace strata::buffers
