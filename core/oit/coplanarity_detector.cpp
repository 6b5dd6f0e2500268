#include "oit/coplanarity_detector.hpp"

#include "common/bindings.h"
#include "gl/shader_program.hpp"
#include "oit/abuffer_node.h"
#include "oit/coplanarity_bindings.h"
#include "oit/draw_transparent.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>

namespace strata {
namespace {

constexpr std::uint64_t kNodeBytes = sizeof(gpu::FragmentNode);
static_assert(gpu::COPLANARITY_BINS == unsigned(kCoplanarityBins));

}  // namespace

void CoplanarityDetector::prepare(glm::ivec2 size) {
    if (!storeProgram_.program) {
        storeProgram_ = buildSceneProgram("oit/abuffer_store.frag.glsl");
        resolveProgram_ = gl::buildProgram({"oit/coplanarity_detect.comp.glsl"});
        capacityLocation_ = glGetUniformLocation(storeProgram_.id(), "uCapacity");
        tileLocation_ = glGetUniformLocation(resolveProgram_.id(), "uTile");
        counter_ = gl::Buffer::create();
        glNamedBufferStorage(counter_.id(), sizeof(GLuint), nullptr, GL_DYNAMIC_STORAGE_BIT | GL_MAP_READ_BIT);
        totals_ = gl::Buffer::create();
        glNamedBufferStorage(totals_.id(), gpu::COPLANARITY_TOTALS * sizeof(GLuint), nullptr,
                             GL_DYNAMIC_STORAGE_BIT | GL_MAP_READ_BIT);
    }
    if (size != size_) {
        heads_ = gl::createTexture2D(GL_R32UI, size.x, size.y);
        largestLayer_ = gl::createTexture2D(GL_RG32UI, size.x, size.y);
        heatmap_ = gl::createTexture2D(GL_RGBA16F, size.x, size.y);
        size_ = size;
    }
}

void CoplanarityDetector::ensurePool() {
    if (poolCapacity_ == capacity_) return;
    gl::allocateBuffer(nodes_, capacity_ * kNodeBytes, GL_DYNAMIC_COPY, "coplanarity detector node pool");
    poolCapacity_ = capacity_;
}

CoplanarityStats CoplanarityDetector::detect(const FrameContext& frame) {
    prepare(frame.size);
    const std::uint64_t maxNodes = gl::storageBlockElements(kNodeBytes, maxBlockMiB_);
    // As abuffer: two fragments per pixel to start, then what the previous frame needed.
    if (capacity_ == 0) capacity_ = std::uint64_t(frame.size.x) * std::uint64_t(frame.size.y) * 2;
    capacity_ = std::clamp<std::uint64_t>(capacity_, 1, maxNodes);
    ensurePool();
    const std::array<GLuint, gpu::COPLANARITY_TOTALS> zeros{};
    glNamedBufferSubData(totals_.id(), 0, sizeof zeros, zeros.data());
    passes_ = 0;
    tiles_ = 0;
    regrows_ = 0;

    CoplanarityStats stats;
    std::vector<Tile> tiles{{{0, 0}, frame.size}};
    std::uint64_t largestTile = 0;
    while (!tiles.empty()) {
        Tile tile = tiles.back();
        tiles.pop_back();
        const std::uint64_t needed = store(frame, tile);
        if (needed > capacity_) {
            if (needed <= maxNodes) {
                capacity_ = std::min<std::uint64_t>(maxNodes, needed + needed / 8);
                ensurePool();
                ++regrows_;
                tiles.push_back(tile);
                continue;
            }
            if (tile.size.x * tile.size.y <= 1)
                throw std::runtime_error("coplanarity detector: one pixel holds " + std::to_string(needed) +
                                         " fragments, more than the largest storage block");
            capacity_ = maxNodes;
            ensurePool();
            // Halve the longer side; both halves go back on the list.
            if (tile.size.x >= tile.size.y) {
                const int half = tile.size.x / 2;
                tiles.push_back({tile.origin, {half, tile.size.y}});
                tiles.push_back({{tile.origin.x + half, tile.origin.y}, {tile.size.x - half, tile.size.y}});
            } else {
                const int half = tile.size.y / 2;
                tiles.push_back({tile.origin, {tile.size.x, half}});
                tiles.push_back({{tile.origin.x, tile.origin.y + half}, {tile.size.x, tile.size.y - half}});
            }
            continue;
        }
        resolve(frame, tile);
        stats.fragments += needed;
        largestTile = std::max(largestTile, needed);
        ++tiles_;
    }
    glDisable(GL_SCISSOR_TEST);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::array<GLuint, gpu::COPLANARITY_TOTALS> totals{};
    glGetNamedBufferSubData(totals_.id(), 0, sizeof totals, totals.data());
    for (int i = 0; i < kCoplanarityBins; ++i) stats.pixelsByLargestLayer[std::size_t(i)] = totals[std::size_t(i)];
    stats.layers = totals[gpu::COPLANARITY_TOTAL_LAYERS];
    // Memory follows the fragments present: give back a pool four times larger than needed.
    if (largestTile * 4 < capacity_) capacity_ = std::max<std::uint64_t>(largestTile + largestTile / 8, 1024);
    return stats;
}

std::uint64_t CoplanarityDetector::store(const FrameContext& frame, const Tile& tile) {
    gl::ScopedPass pass(frame.timer, std::string(kPassPrefix) + "store");
    GLuint zero = 0;
    glClearTexImage(heads_.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    glNamedBufferSubData(counter_.id(), 0, sizeof(GLuint), &zero);
    // The output framebuffer carries the opaque depth; colour writes stay off.
    glBindFramebuffer(GL_FRAMEBUFFER, frame.targets.outputFramebuffer());
    setTransparentDepthState(frame);
    glEnable(GL_SCISSOR_TEST);
    glScissor(tile.origin.x, tile.origin.y, tile.size.x, tile.size.y);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glBindImageTexture(gpu::BIND_HEADS, heads_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
    glBindBufferBase(GL_ATOMIC_COUNTER_BUFFER, gpu::BIND_COUNTERS, counter_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BIND_NODES, nodes_.id());
    glProgramUniform1ui(storeProgram_.id(), capacityLocation_, GLuint(std::min<std::uint64_t>(capacity_, 0xFFFFFFFFu)));
    drawTransparent(frame, storeProgram_, frame.transparentOrder);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT |
                    GL_ATOMIC_COUNTER_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    ++passes_;
    GLuint count = 0;
    glGetNamedBufferSubData(counter_.id(), 0, sizeof(GLuint), &count);
    return count;
}

void CoplanarityDetector::resolve(const FrameContext& frame, const Tile& tile) {
    gl::ScopedPass pass(frame.timer, std::string(kPassPrefix) + "resolve");
    const GLuint program = resolveProgram_.id();
    glBindImageTexture(gpu::BIND_HEADS, heads_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
    glBindImageTexture(gpu::BIND_LARGEST_LAYER, largestLayer_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RG32UI);
    glBindImageTexture(gpu::BIND_RESOLVE_OUTPUT, heatmap_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BIND_NODES, nodes_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BIND_COPLANARITY_TOTALS, totals_.id());
    setDepthOrderUniforms(frame, program);
    glProgramUniform4i(program, tileLocation_, tile.origin.x, tile.origin.y, tile.size.x, tile.size.y);
    glUseProgram(program);
    constexpr int group = int(gpu::RESOLVE_GROUP_SIZE);
    glDispatchCompute(GLuint((tile.size.x + group - 1) / group), GLuint((tile.size.y + group - 1) / group), 1);
    // Next: the totals are read back, the images read as textures (present, read-back), and the
    // next tile's store reuses the heads and nodes.
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
                    GL_TEXTURE_UPDATE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    ++passes_;
}

std::uint64_t CoplanarityDetector::bytes() const {
    const std::uint64_t pixels = std::uint64_t(size_.x) * std::uint64_t(size_.y);
    // Nodes, heads (4 B), largest layer and fragments (8 B), heatmap colour (rgba16f, 8 B),
    // counter and totals.
    return poolCapacity_ * kNodeBytes + pixels * (4 + 8 + 8) + sizeof(GLuint) * (1 + gpu::COPLANARITY_TOTALS);
}

CoplanarityDetector::Pixels CoplanarityDetector::readPixels() const {
    const std::size_t n = std::size_t(size_.x) * std::size_t(size_.y);
    std::vector<std::uint32_t> pairs(n * 2);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureImage(largestLayer_.id(), 0, GL_RG_INTEGER, GL_UNSIGNED_INT,
                      GLsizei(pairs.size() * sizeof(std::uint32_t)), pairs.data());
    Pixels out;
    out.largestLayer.resize(n);
    out.fragments.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        out.largestLayer[i] = pairs[2 * i];
        out.fragments[i] = pairs[2 * i + 1];
    }
    return out;
}

Image CoplanarityDetector::readHeatmap() const {
    Image image(size_.x, size_.y);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureImage(heatmap_.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(image.rgba.size() * sizeof(float)),
                      image.rgba.data());
    return image;
}

}  // namespace strata
