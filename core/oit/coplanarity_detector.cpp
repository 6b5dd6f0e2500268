#include "oit/coplanarity_detector.hpp"

#include "render/texture_readback.hpp"

#include "common/bindings.h"
#include "gl/shader_program.hpp"
#include "oit/coplanarity_bindings.h"
#include "oit/draw_transparent.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>

namespace strata {
namespace {

static_assert(gpu::COPLANARITY_BINS == unsigned(kCoplanarityBins));

}  // namespace

void CoplanarityDetector::prepare(glm::ivec2 size) {
    if (!storeProgram_.program) {
        storeProgram_ = buildSceneProgram("oit/abuffer_store.frag.glsl");
        resolveProgram_ = gl::buildProgram({"oit/coplanarity_detect.comp.glsl"});
        tileLocation_ = glGetUniformLocation(resolveProgram_.id(), "uTile");
        totals_ = gl::Buffer::create();
        glNamedBufferStorage(totals_.id(), gpu::COPLANARITY_TOTALS * sizeof(GLuint), nullptr,
                             GL_DYNAMIC_STORAGE_BIT | GL_MAP_READ_BIT);
    }
    if (size != size_) {
        largestLayer_ = gl::createTexture2D(GL_RG32UI, size.x, size.y);
        heatmap_ = gl::createTexture2D(GL_RGBA16F, size.x, size.y);
        size_ = size;
    }
}

CoplanarityStats CoplanarityDetector::detect(const FrameContext& frame) {
    prepare(frame.size);
    const std::array<GLuint, gpu::COPLANARITY_TOTALS> zeros{};
    glNamedBufferSubData(totals_.id(), 0, sizeof zeros, zeros.data());
    int resolves = 0;
    // abuffer's lists, grown and tiled alike (oit/fragment_lists.hpp).
    const FragmentLists::Run run = lists_.render(frame, storeProgram_, 0, maxBlockMiB_, [&](const FragmentLists::Tile& tile) {
        resolve(frame, tile);
        ++resolves;
    });
    passes_ = run.passes + resolves;
    tiles_ = run.tiles;
    regrows_ = run.regrows;
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    CoplanarityStats stats;
    stats.fragments = run.fragments;
    std::array<GLuint, gpu::COPLANARITY_TOTALS> totals{};
    glGetNamedBufferSubData(totals_.id(), 0, sizeof totals, totals.data());
    for (int i = 0; i < kCoplanarityBins; ++i) stats.pixelsByLargestLayer[std::size_t(i)] = totals[std::size_t(i)];
    stats.layers = totals[gpu::COPLANARITY_TOTAL_LAYERS];
    return stats;
}

void CoplanarityDetector::resolve(const FrameContext& frame, const FragmentLists::Tile& tile) {
    gl::ScopedPass pass(frame.timer, std::string(kPassPrefix) + "resolve");
    const GLuint program = resolveProgram_.id();
    glBindImageTexture(gpu::BIND_LARGEST_LAYER, largestLayer_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RG32UI);
    glBindImageTexture(gpu::BIND_RESOLVE_OUTPUT, heatmap_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
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
    // The lists (nodes, heads, counter), largest layer and fragments (8 B), heatmap colour
    // (rgba16f, 8 B) and totals.
    return lists_.bytes() + pixels * (8 + 8) + sizeof(GLuint) * gpu::COPLANARITY_TOTALS;
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

Image CoplanarityDetector::readHeatmap() const { return readRgbaTexture(heatmap_.id(), size_); }

}  // namespace strata
