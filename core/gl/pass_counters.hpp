#pragma once
// Atomic counters one pass writes and the CPU reads later, without waiting for the passes issued
// after it. Reading a counter buffer with glGetBufferSubData may wait for everything queued before
// the read, so a technique that reads pass k's counts after issuing pass k + 1
// (PeelLoop::runAhead) would wait for pass k + 1 too; a fence behind pass k waits for it alone.
//
// Two buffers: the shaders count in one of GPU memory, and after the pass a 16-byte copy lands in
// a persistently mapped, coherent one the CPU reads. Counting in the mapped buffer itself put the
// atomics in host memory on NVIDIA (each a PCIe round trip, all on one address): dual's blend took
// 320 ms a frame on an H200 at 1280x720 (docs/gpu-h200-session8.md), against 0.3 ms on llvmpipe,
// where all memory is host memory.
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
    // After the pass: copies the counts to the mapped buffer and fences the copy.
    void fence();
    // Waits for the fence and returns the counters. Throws std::runtime_error when the GPU has
    // not finished the pass within a minute.
    std::array<std::uint32_t, kSlots> read();

private:
    Buffer counters_;  // GPU memory: the shaders' atomics
    Buffer readback_;  // mapped: the copy the CPU reads
    const volatile std::uint32_t* mapped_ = nullptr;
    GLsync fence_ = nullptr;
};

}  // namespace strata::gl
