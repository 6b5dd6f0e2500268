#include "oit/screendoor/alpha_masks.hpp"

#include "oit/screendoor/screendoor_bindings.h"

#include <random>

namespace strata::screendoor {

std::vector<std::uint8_t> makeAlphaMasks(int side, std::uint32_t seed) {
    const std::size_t texels = std::size_t(side) * side;
    const std::uint32_t layers = gpu::ALPHA_LEVELS + 1;
    std::vector<std::uint8_t> bits(texels * layers);
    for (std::uint32_t level = 0; level < layers; ++level) {
        // One stream per layer, so a layer does not change when the number of levels does.
        std::mt19937 random(seed * 0x9e3779b9u + level);
        const double keep = double(level) / double(gpu::ALPHA_LEVELS);
        for (std::size_t i = 0; i < texels; ++i) {
            const double u = double(random() >> 8) * 0x1.0p-24;  // uniform in [0, 1), 24 bits
            bits[level * texels + i] = u < keep ? 1 : 0;
        }
    }
    return bits;
}

void AlphaMasks::bind(int side, std::uint32_t seed) {
    if (!texture_ || side != side_ || seed != seed_) {
        const std::vector<std::uint8_t> bits = makeAlphaMasks(side, seed);
        texture_ = gl::createTexture(GL_TEXTURE_2D_ARRAY);
        const GLsizei layers = GLsizei(gpu::ALPHA_LEVELS + 1);
        glTextureStorage3D(texture_.id(), 1, GL_R8UI, side, side, layers);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTextureSubImage3D(texture_.id(), 0, 0, 0, 0, side, side, layers, GL_RED_INTEGER, GL_UNSIGNED_BYTE, bits.data());
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);  // the default, which other uploads assume
        glTextureParameteri(texture_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(texture_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        side_ = side;
        seed_ = seed;
    }
    glBindTextureUnit(gpu::BIND_ALPHA_MASKS, texture_.id());
}

std::uint64_t AlphaMasks::bytes() const {
    return std::uint64_t(side_) * side_ * (gpu::ALPHA_LEVELS + 1);
}

}  // namespace strata::screendoor
