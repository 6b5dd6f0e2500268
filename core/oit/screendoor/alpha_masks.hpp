#pragma once
// The random binary masks of the screen-door techniques: one layer per alpha level, each texel of
// layer l set with probability l / ALPHA_LEVELS from a seeded generator (Sen et al. 4.2.2: "for
// each texel a random number is produced and compared to the alpha level"). Layer 0 is empty
// (alpha 0 is invisible) and the last layer full (alpha 1 is opaque). The same seed and size give
// the same masks on every machine: the generator is std::mt19937 and the conversion to [0, 1)
// is written here, not left to a standard library's distribution.
#include "gl/objects.hpp"

#include <cstdint>
#include <vector>

namespace strata::screendoor {

// The mask bits on the CPU, layer after layer, row after row (0 or 1).
std::vector<std::uint8_t> makeAlphaMasks(int side, std::uint32_t seed);

class AlphaMasks {
public:
    // (Re)builds the r8ui texture array when the side or the seed changed; binds it to
    // BIND_ALPHA_MASKS.
    void bind(int side, std::uint32_t seed);
    std::uint64_t bytes() const;

private:
    gl::Texture texture_;
    int side_ = 0;
    std::uint32_t seed_ = 0;
};

}  // namespace strata::screendoor
