#pragma once
// Atomic counters one pass writes and the CPU reads later, without waiting for the passes issued
// after it: a persistently mapped, coherent buffer, and a fence behind the pass. Reading a
// counter buffer with glGetBufferSubData may wait for everything queued before the read, so a
// technique that reads pass k's counts after issuing pass k + 1 (PeelLoop::runAhead) would wait
// for pass k + 1 too; the fence waits for pass k only.
#include "gl/objects.hpp"

#include <array>
#include <cstdint>

namespace strata::gl {

class PassCounters {
public:
    static constexpr int kSlots = 4;  // uints, at byte offsets 0, 4, 8, 12

    PassCounters() = default;
    ~PassCounters();
    PassCounters(const PassCounters&) = delete;
    PassCounters& operator=(const PassCounters&) = delete;
    PassCounters(PassCounters&& other) noexcept;
    PassCounters& operator=(PassCounters&& other) noexcept;

    // Before the pass: creates the buffer on first use and zeroes it (on the GPU, in order).
    void reset();
    // Binds it as the atomic counter buffer at `binding`.
    void bind(GLuint binding) const;
    // After the pass: makes its writes visible to the mapping and fences them.
    void fence();
    // Waits for the fence and returns the counters. Throws std::runtime_error when the GPU has
    // not finished the pass within a minute.
    std::array<std::uint32_t, kSlots> read();

private:
    Buffer buffer_;
    const volatile std::uint32_t* mapped_ = nullptr;
    GLsync fence_ = nullptr;
};

}  // namespace strata::gl
