// Batches nearest first (render/batch_order.hpp): runs move whole, by their nearest member.
#include "render/batch_order.hpp"

#include <doctest/doctest.h>

using namespace strata;

namespace {

// Objects 0..n-1 with a batch key and a nearest depth each.
struct Objects {
    std::vector<int> key;
    std::vector<float> depth;
    bool sameRun(int a, int b) const { return key[std::size_t(a)] == key[std::size_t(b)]; }
    float nearest(int o) const { return depth[std::size_t(o)]; }
};

std::vector<int> ordered(std::vector<int> order, const Objects& objects) {
    orderRunsNearestFirst(
        order, [&](int a, int b) { return objects.sameRun(a, b); }, [&](int o) { return objects.nearest(o); });
    return order;
}

}  // namespace

TEST_CASE("layers given farthest first come out nearest first") {
    Objects layers{{0, 1, 2, 3}, {4.0f, 3.0f, 2.0f, 1.0f}};
    CHECK(ordered({0, 1, 2, 3}, layers) == std::vector<int>{3, 2, 1, 0});
}

TEST_CASE("a run moves whole, by its nearest member, and keeps its own order") {
    // Runs: {0, 1, 2} (key 7, nearest 1.5), {3} (key 8, at 2), {4, 5} (key 9, nearest 0.5).
    Objects o{{7, 7, 7, 8, 9, 9}, {5.0f, 1.5f, 9.0f, 2.0f, 3.0f, 0.5f}};
    CHECK(ordered({0, 1, 2, 3, 4, 5}, o) == std::vector<int>{4, 5, 0, 1, 2, 3});
}

TEST_CASE("equal depths keep the given order; one run and no objects are left alone") {
    Objects tied{{0, 1, 2}, {1.0f, 1.0f, 1.0f}};
    CHECK(ordered({2, 0, 1}, tied) == std::vector<int>{2, 0, 1});
    Objects oneRun{{3, 3, 3}, {3.0f, 1.0f, 2.0f}};
    CHECK(ordered({0, 1, 2}, oneRun) == std::vector<int>{0, 1, 2});
    CHECK(ordered({}, oneRun).empty());
}

TEST_CASE("a key seen again after another run starts a run of its own") {
    // Runs are consecutive objects only: 0 and 2 share key 1 but are apart.
    Objects o{{1, 2, 1}, {3.0f, 2.0f, 1.0f}};
    CHECK(ordered({0, 1, 2}, o) == std::vector<int>{2, 1, 0});
}
