#include "oit/peeling/layer_storage.hpp"

#include "common/bindings.h"
#include "oit/abuffer_node.h"
#include "oit/buffers/buffer_bindings.h"

#include <algorithm>

namespace strata::peeling {
namespace {

constexpr std::uint64_t kNodeBytes = sizeof(gpu::FragmentNode);
constexpr std::uint64_t kEntryBytes = sizeof(gpu::FragmentEntry);
constexpr std::uint64_t kCounterBytes = 2 * sizeof(GLuint);

}  // namespace

gl::Defines LayerStorage::defines() const {
    switch (kind_) {
    case LayerStore::List: return {{"LAYER_LIST", ""}};
    case LayerStore::Fab: return {{"LAYER_FAB", ""}};
    case LayerStore::KBuffer: break;
    }
    return {{"LAYER_KB", ""}};
}

void LayerStorage::prepare(glm::ivec2 size, int sides, int capacity, double maxBlockMiB) {
    if (!counters_) {
        counters_ = gl::Buffer::create();
        glNamedBufferStorage(counters_.id(), kCounterBytes, nullptr, GL_DYNAMIC_STORAGE_BIT | GL_MAP_READ_BIT);
    }
    const bool resized = size != size_ || sides != sides_;
    size_ = size;
    sides_ = sides;
    const std::uint64_t pixels = std::uint64_t(size.x) * std::uint64_t(size.y) * std::uint64_t(sides);
    if (resized && kind_ != LayerStore::KBuffer) pixels_ = gl::createTexture2D(GL_R32UI, size.x, size.y * sides);
    if (kind_ == LayerStore::List) {
        maxNodes_ = gl::storageBlockElements(kNodeBytes, maxBlockMiB);
        // First frame: one node per pixel and side (one layer covering the frame); later frames
        // keep what the previous one needed.
        if (poolNodes_ == 0 || resized) allocatePool(std::clamp<std::uint64_t>(pixels, 1, maxNodes_));
        else if (poolNodes_ > maxNodes_) allocatePool(maxNodes_);
    } else if (resized || capacity != capacity_) {
        gl::allocateBuffer(storage_, pixels * std::uint64_t(capacity) * kEntryBytes, GL_DYNAMIC_COPY,
                           (label_ + " entries").c_str());
    }
    capacity_ = capacity;
    frameLargest_ = 0;
    split_ = false;
}

void LayerStorage::allocatePool(std::uint64_t nodes) {
    gl::allocateBuffer(storage_, nodes * kNodeBytes, GL_DYNAMIC_COPY, (label_ + " node pool").c_str());
    poolNodes_ = nodes;
}

void LayerStorage::bind() const {
    switch (kind_) {
    case LayerStore::List:
        glBindImageTexture(gpu::BIND_HEADS, pixels_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BIND_NODES, storage_.id());
        break;
    case LayerStore::Fab:
        glBindImageTexture(gpu::BIND_PIXEL_COUNTS, pixels_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BIND_ENTRIES, storage_.id());
        break;
    case LayerStore::KBuffer: glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BIND_ENTRIES, storage_.id()); break;
    }
    glBindBufferBase(GL_ATOMIC_COUNTER_BUFFER, gpu::BIND_COUNTERS, counters_.id());
}

void LayerStorage::setUniforms(GLuint program) const {
    const bool list = kind_ == LayerStore::List;
    glProgramUniform1ui(program, glGetUniformLocation(program, "uWidth"), GLuint(size_.x));
    glProgramUniform1i(program, glGetUniformLocation(program, "uHeight"), size_.y);
    glProgramUniform1ui(program, glGetUniformLocation(program, "uCapacity"),
                        GLuint(list ? std::min<std::uint64_t>(poolNodes_, 0xFFFFFFFFu) : std::uint64_t(capacity_)));
    if (list) {
        glProgramUniform1ui(program, glGetUniformLocation(program, "uFrontLimit"), GLuint(frontLimit_));
        glProgramUniform1ui(program, glGetUniformLocation(program, "uBackLimit"), GLuint(backLimit_));
    }
}

void LayerStorage::beginPass(GLuint program) {
    const GLuint zero = 0, unclaimed = 0xFFFFFFFFu;
    if (kind_ == LayerStore::KBuffer)
        glClearNamedBufferData(storage_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &unclaimed);
    else
        glClearTexImage(pixels_.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    const GLuint zeros[2] = {0, 0};
    glNamedBufferSubData(counters_.id(), 0, sizeof(zeros), zeros);
    // Both sides may use the whole pool: the pass is repeated when together they need more.
    if (!split_) frontLimit_ = backLimit_ = std::min<std::uint64_t>(poolNodes_, 0xFFFFFFFFu);
    bind();
    setUniforms(program);
}

LayerCounts LayerStorage::endPass() {
    // TEXTURE_UPDATE: the next pass clears the pixel image these image atomics wrote.
    glMemoryBarrier(GL_ATOMIC_COUNTER_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT |
                    GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
    GLuint c[2] = {0, 0};
    glGetNamedBufferSubData(counters_.id(), 0, sizeof(c), c);
    LayerCounts out;
    if (kind_ != LayerStore::List) {
        out.stored = c[0];
        out.overflow = c[1];
        out.inLayer = out.stored + out.overflow;
        return out;
    }
    const std::uint64_t front = c[0], back = c[1], needed = front + back;
    frameLargest_ = std::max(frameLargest_, needed);
    if (needed <= poolNodes_ || split_) {
        out.inLayer = needed;
        out.stored = std::min(front, frontLimit_) + std::min(back, backLimit_);
        out.overflow = needed - out.stored;
        split_ = false;
        return out;
    }
    out.repeat = true;
    if (needed <= maxNodes_) {
        allocatePool(std::min<std::uint64_t>(maxNodes_, needed + needed / 8));
        return out;
    }
    // More than the largest block holds: the front keeps what it can, the back the rest of the
    // pool, so the two never overlap; the repeated pass counts what neither kept.
    if (poolNodes_ < maxNodes_) allocatePool(maxNodes_);
    frontLimit_ = std::min<std::uint64_t>(front, poolNodes_);
    backLimit_ = poolNodes_ - frontLimit_;
    split_ = true;
    return out;
}

void LayerStorage::bindForResolve(GLuint program) const {
    bind();
    setUniforms(program);
}

void LayerStorage::endFrame() {
    if (kind_ != LayerStore::List) return;
    const std::uint64_t floor = std::min<std::uint64_t>(1024, maxNodes_);
    if (frameLargest_ * 4 < poolNodes_ && poolNodes_ > floor)
        allocatePool(std::max<std::uint64_t>(frameLargest_ + frameLargest_ / 8, floor));
}

std::uint64_t LayerStorage::bytes() const {
    const std::uint64_t pixels = std::uint64_t(size_.x) * std::uint64_t(size_.y) * std::uint64_t(sides_);
    switch (kind_) {
    case LayerStore::List: return poolNodes_ * kNodeBytes + pixels * 4 + kCounterBytes;
    case LayerStore::Fab: return pixels * (std::uint64_t(capacity_) * kEntryBytes + 4) + kCounterBytes;
    case LayerStore::KBuffer: break;
    }
    return pixels * std::uint64_t(capacity_) * kEntryBytes + kCounterBytes;
}

}  // namespace strata::peeling
