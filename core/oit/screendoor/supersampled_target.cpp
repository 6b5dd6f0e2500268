#include "oit/screendoor/supersampled_target.hpp"

#include "common/bindings.h"
#include "gl/shader_program.hpp"
#include "oit/draw_transparent.hpp"
#include "oit/screendoor/screendoor_bindings.h"

#include <algorithm>
#include <bit>
#include <stdexcept>

namespace strata::screendoor {

std::vector<Tile> supersampleTiles(glm::ivec2 frameSize, int factor) {
    const int side = std::max(1, kMaxSupersampledSide / factor);
    std::vector<Tile> tiles;
    for (int y = 0; y < frameSize.y; y += side)
        for (int x = 0; x < frameSize.x; x += side)
            tiles.push_back({{x, y}, {std::min(side, frameSize.x - x), std::min(side, frameSize.y - y)}});
    return tiles;
}

glm::mat4 tileClipTransform(glm::ivec2 frameSize, const Tile& tile) {
    // NDC range [a, b] of the tile goes to [-1, 1]: x' = s x + o with s = 2 / (b - a) and
    // o = -(a + b) / (b - a); in clip space the offset multiplies w.
    glm::mat4 m(1.0f);
    for (int axis = 0; axis < 2; ++axis) {
        const float a = 2.0f * float(tile.origin[axis]) / float(frameSize[axis]) - 1.0f;
        const float b = 2.0f * float(tile.origin[axis] + tile.size[axis]) / float(frameSize[axis]) - 1.0f;
        m[axis][axis] = 2.0f / (b - a);
        m[3][axis] = -(a + b) / (b - a);
    }
    return m;
}

int SupersampledTarget::passesPerTile(int factor) {
    return 1 + std::max(1, std::countr_zero(unsigned(factor)));
}

std::uint64_t SupersampledTarget::bytes() const {
    std::uint64_t total = 0;
    for (int level = 0; level < std::max(levels_, 1); ++level)
        total += std::uint64_t(std::max(1, allocated_.x >> level)) * std::max(1, allocated_.y >> level) * 16;
    return total + std::uint64_t(allocated_.x) * allocated_.y * 4;
}

void SupersampledTarget::allocate(glm::ivec2 samples, int levels) {
    if (samples == allocated_ && levels == levels_ && color_) return;
    // Levels 0 .. log2(n) - 1: the samples and every average but the last, which is the output.
    color_ = gl::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(color_.id(), std::max(levels, 1), GL_RGBA32F, samples.x, samples.y);
    glTextureParameteri(color_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(color_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    depth_ = gl::createTexture2D(GL_DEPTH_COMPONENT32F, samples.x, samples.y);
    samplesFbo_ = gl::Framebuffer::create();
    glNamedFramebufferTexture(samplesFbo_.id(), GL_COLOR_ATTACHMENT0, color_.id(), 0);
    glNamedFramebufferTexture(samplesFbo_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);
    if (glCheckNamedFramebufferStatus(samplesFbo_.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("screen-door: supersampled framebuffer incomplete");
    averageFbo_ = gl::Framebuffer::create();
    allocated_ = samples;
    levels_ = levels;
}

namespace {

// `area` (output pixels) in the coordinates of a level of the tile where each output pixel is
// `scale` texels a side: the rectangle scissored there.
void scissorTo(const Tile& tile, const PixelRect& area, int scale) {
    glEnable(GL_SCISSOR_TEST);
    const glm::ivec2 origin = (area.origin - tile.origin) * scale;
    glScissor(origin.x, origin.y, area.size.x * scale, area.size.y * scale);
}

}  // namespace

void SupersampledTarget::begin(const FrameContext& frame, const Tile& tile, int factor, std::optional<PixelRect> area) {
    if (!fill_) {
        fill_ = gl::buildProgram({"common/fullscreen.vert.glsl", "oit/screendoor/supersample_fill.frag.glsl"});
        average_ = gl::buildProgram({"common/fullscreen.vert.glsl", "oit/screendoor/box_average.frag.glsl"});
    }
    const int maxTile = std::max(1, kMaxSupersampledSide / factor);
    const glm::ivec2 tileCapacity = glm::min(glm::ivec2(maxTile), frame.size);
    allocate(tileCapacity * factor, std::countr_zero(unsigned(factor)));
    glBindFramebuffer(GL_FRAMEBUFFER, samplesFbo_.id());
    glViewport(0, 0, tile.size.x * factor, tile.size.y * factor);
    glProgramUniform2i(fill_.id(), glGetUniformLocation(fill_.id(), "uTileOrigin"), tile.origin.x, tile.origin.y);
    glProgramUniform1i(fill_.id(), glGetUniformLocation(fill_.id(), "uFactor"), factor);
    glBindTextureUnit(gpu::BIND_OPAQUE_COLOR, frame.targets.opaqueColor());
    glBindTextureUnit(gpu::BIND_OPAQUE_DEPTH, frame.targets.depth());
    // The fill writes depth, so the test must be on (GL writes no depth with it off) and pass always.
    glUseProgram(fill_.id());
    glBindVertexArray(frame.targets.emptyVertexArray());
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_TRUE);
    if (area) scissorTo(tile, *area, factor);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    // Masked fragments are opaque: the nearest one a sample keeps wins, in any draw order.
    glDepthFunc(GL_GREATER);
    glDisable(GL_CULL_FACE);
}

void SupersampledTarget::resolve(const FrameContext& frame, const Tile& tile, int factor, std::optional<PixelRect> area) {
    const PixelRect part = area.value_or(PixelRect{tile.origin, tile.size});
    const int steps = std::countr_zero(unsigned(factor));
    if (steps == 0) {
        glDisable(GL_SCISSOR_TEST);
        const glm::ivec2 from = part.origin - tile.origin;
        glBlitNamedFramebuffer(samplesFbo_.id(), frame.targets.outputFramebuffer(), from.x, from.y, from.x + part.size.x,
                               from.y + part.size.y, part.origin.x, part.origin.y, part.origin.x + part.size.x,
                               part.origin.y + part.size.y, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        return;
    }
    const GLint originLocation = glGetUniformLocation(average_.id(), "uDestinationOrigin");
    for (int level = 0; level < steps; ++level) {
        // The source level is the only level the sampler sees, so writing the next one is no
        // feedback loop.
        glTextureParameteri(color_.id(), GL_TEXTURE_BASE_LEVEL, level);
        glTextureParameteri(color_.id(), GL_TEXTURE_MAX_LEVEL, level);
        glBindTextureUnit(gpu::BIND_DOWNSAMPLE_SOURCE, color_.id());
        const bool last = level + 1 == steps;
        const int scale = factor >> (level + 1);  // texels of this level a side per output pixel
        const glm::ivec2 size = tile.size * scale;
        if (last) {
            glBindFramebuffer(GL_FRAMEBUFFER, frame.targets.outputFramebuffer());
            glViewport(tile.origin.x, tile.origin.y, size.x, size.y);
            glProgramUniform2i(average_.id(), originLocation, tile.origin.x, tile.origin.y);
            scissorTo(Tile{}, part, 1);  // the output's own pixels
        } else {
            glNamedFramebufferTexture(averageFbo_.id(), GL_COLOR_ATTACHMENT0, color_.id(), level + 1);
            glBindFramebuffer(GL_FRAMEBUFFER, averageFbo_.id());
            glViewport(0, 0, size.x, size.y);
            glProgramUniform2i(average_.id(), originLocation, 0, 0);
            scissorTo(tile, part, scale);
        }
        drawFullscreen(frame, average_.id());
    }
    glDisable(GL_SCISSOR_TEST);
    glTextureParameteri(color_.id(), GL_TEXTURE_BASE_LEVEL, 0);
    glTextureParameteri(color_.id(), GL_TEXTURE_MAX_LEVEL, 1000);
    glViewport(0, 0, frame.size.x, frame.size.y);
}

}  // namespace strata::screendoor
