#include "oit/buffers/prefix_sum.hpp"

#include "gl/shader_program.hpp"

#include <stdexcept>

namespace strata::buffers {
namespace {

std::uint64_t blocks(std::uint64_t count) { return (count + PrefixSum::kBlock - 1) / PrefixSum::kBlock; }

}  // namespace

std::uint64_t PrefixSum::scratchBytes(std::uint64_t count) {
    std::uint64_t bytes = 0;
    for (std::uint64_t n = count;;) {
        std::uint64_t groups = blocks(n);
        bytes += groups * 4;
        if (groups <= 1) return bytes;
        n = groups;
    }
}

std::uint32_t PrefixSum::scan(GLuint buffer, std::uint64_t count) {
    if (count == 0) return 0;
    if (count > 0xFFFFFFFFull) throw std::invalid_argument("prefix sum: more than 2^32 elements");
    if (!scan_) {
        scan_ = gl::buildProgram({"oit/buffers/prefix_scan.comp.glsl"});
        add_ = gl::buildProgram({"oit/buffers/prefix_add.comp.glsl"});
        scanCount_ = glGetUniformLocation(scan_.id(), "uCount");
        addCount_ = glGetUniformLocation(add_.id(), "uCount");
    }
    // One block-total buffer per level, kept between calls and grown when needed.
    bytes_ = 0;
    std::size_t level = 0;
    for (std::uint64_t n = count;; ++level) {
        std::uint64_t groups = blocks(n);
        if (sums_.size() <= level) {
            sums_.emplace_back();
            sumsSize_.push_back(0);
        }
        if (sumsSize_[level] < groups) {
            gl::allocateBuffer(sums_[level], groups * 4, GL_DYNAMIC_COPY, "prefix-sum block totals");
            sumsSize_[level] = groups;
        }
        bytes_ += sumsSize_[level] * 4;
        if (groups <= 1) break;
        n = groups;
    }
    scanLevel(buffer, 0, count);
    // The top level has one block: its total is the whole total.
    std::uint32_t total = 0;
    glGetNamedBufferSubData(sums_[level].id(), 0, 4, &total);
    return total;
}

void PrefixSum::scanLevel(GLuint data, std::size_t level, std::uint64_t count) {
    std::uint64_t groups = blocks(count);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BIND_SCAN_DATA, data);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BIND_SCAN_SUMS, sums_[level].id());
    glUseProgram(scan_.id());
    glProgramUniform1ui(scan_.id(), scanCount_, GLuint(count));
    glDispatchCompute(GLuint(groups), 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    if (groups <= 1) return;
    scanLevel(sums_[level].id(), level + 1, groups);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BIND_SCAN_DATA, data);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BIND_SCAN_SUMS, sums_[level].id());
    glUseProgram(add_.id());
    glProgramUniform1ui(add_.id(), addCount_, GLuint(count));
    glDispatchCompute(GLuint(groups), 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

}  // namespace strata::buffers
