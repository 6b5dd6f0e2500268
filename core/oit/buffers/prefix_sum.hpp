#pragma once
// In-place exclusive prefix sum of uint32 values in a GL buffer, on the GPU: a work-efficient
// block scan (shaders/oit/buffers/prefix_scan.comp.glsl, gpu::SCAN_BLOCK elements per group) applied
// recursively to the block totals, then the totals added back. Correct for any count >= 1.
#include "gl/objects.hpp"
#include "oit/buffers/buffer_bindings.h"

#include <cstdint>
#include <vector>

namespace strata::buffers {

class PrefixSum {
public:
    static constexpr std::uint64_t kBlock = gpu::SCAN_BLOCK;

    // Scans the first `count` uints of `buffer` in place; returns their total.
    std::uint32_t scan(GLuint buffer, std::uint64_t count);

    // Bytes of the block-total buffers a scan of `count` elements uses (one per level).
    static std::uint64_t scratchBytes(std::uint64_t count);
    std::uint64_t bytes() const { return bytes_; }

private:
    void scanLevel(GLuint data, std::size_t level, std::uint64_t count);
    gl::Program scan_, add_;
    GLint scanCount_ = -1, addCount_ = -1;
    std::vector<gl::Buffer> sums_;            // sums_[l]: block totals of level l
    std::vector<std::uint64_t> sumsSize_;
    std::uint64_t bytes_ = 0;
};

}  // namespace strata::buffers
