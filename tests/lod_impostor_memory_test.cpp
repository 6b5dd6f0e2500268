// Impostor memory (lod/impostor_memory.hpp) against the paper's Tables 2 and 3.
#include "lod/impostor_memory.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace strata::lod;

TEST_CASE("lod impostor memory: Table 2 (MB = 1e6 bytes) and Table 3 (36-byte vertices)") {
    const int views[3] = {12, 20, 32};
    const int res[3] = {64, 128, 256};
    const double table2[3][3] = {{0.197, 0.786, 3.146}, {0.328, 1.311, 5.243}, {0.524, 2.097, 8.389}};
    const std::uint64_t table3[3][3] = {{5461, 21845, 87381}, {9102, 36409, 145636}, {14564, 58254, 233017}};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const std::uint64_t bytes = impostorImageBytes(res[j], views[i]);
            CHECK(bytes == 4ull * res[j] * res[j] * views[i]);
            CHECK(std::round(double(bytes) / 1e3) / 1e3 == doctest::Approx(table2[i][j]).epsilon(1e-9));
            CHECK(equivalentVertices(bytes) == table3[i][j]);
        }
    CHECK(impostorImageBytes(64, 12) == 196608);
    CHECK(equivalentVertices(196608) == 5461);
}

TEST_CASE("lod impostor memory: peels and rectangles") {
    CHECK(impostorImageBytes(128, 20, 2) == 2 * impostorImageBytes(128, 20));
    // 4 bytes per (view, peel, slice): the paper's 4 * num_img * layers.
    CHECK(impostorRectangleBytes(20, 1, 64) == 5120);
    CHECK(impostorRectangleBytes(32, 3, 256) == 4ull * 32 * 3 * 256);
    ImpostorMemory m{100, 20, 7};
    CHECK(m.paperTotal() == 120);
    CHECK(m.total() == 127);
    m += ImpostorMemory{1, 2, 3};
    CHECK(m.total() == 133);
}
