#pragma once
// What a layered impostor costs in memory (Schaufler section 4, Tables 2 and 3), exactly.
#include <cstdint>

namespace strata::lod {

// Table 2: 4 bytes (RGBz) per texel, res x res per image, views x peels images.
std::uint64_t impostorImageBytes(int resolution, int views, int peels = 1);
// The bounding rectangles: 4 one-byte extents per (view, peel, slice).
std::uint64_t impostorRectangleBytes(int views, int peels, int slices);
// Table 3: how many textured vertices (36 bytes: position, normal, colour, uv) a polygonal
// model holds in `bytes`, rounded to the nearest vertex as the paper's table does.
std::uint64_t equivalentVertices(std::uint64_t bytes, std::uint64_t bytesPerVertex = 36);

struct ImpostorMemory {
    std::uint64_t images = 0;        // the atlas (Table 2)
    std::uint64_t rectangles = 0;    // the per-slice bounding rectangles
    std::uint64_t vertexBuffer = 0;  // the slice quads' vertex buffer (reported apart: not in the paper)

    std::uint64_t paperTotal() const { return images + rectangles; }
    std::uint64_t total() const { return images + rectangles + vertexBuffer; }
    ImpostorMemory& operator+=(const ImpostorMemory& o) {
        images += o.images;
        rectangles += o.rectangles;
        vertexBuffer += o.vertexBuffer;
        return *this;
    }
};

}  // namespace strata::lod
