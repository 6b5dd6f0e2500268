#include "lod/impostor_memory.hpp"

namespace strata::lod {

std::uint64_t impostorImageBytes(int resolution, int views, int peels) {
    return 4ull * std::uint64_t(resolution) * std::uint64_t(resolution) * std::uint64_t(views) * std::uint64_t(peels);
}

std::uint64_t impostorRectangleBytes(int views, int peels, int slices) {
    return 4ull * std::uint64_t(views) * std::uint64_t(peels) * std::uint64_t(slices);
}

std::uint64_t equivalentVertices(std::uint64_t bytes, std::uint64_t bytesPerVertex) {
    return (bytes + bytesPerVertex / 2) / bytesPerVertex;
}

}  // namespace strata::lod
