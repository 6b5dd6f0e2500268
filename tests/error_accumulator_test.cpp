// The bench's streaming error: frames fed one at a time give the RMSE and maximum of all frames
// taken as one set of pixels, without keeping any frame.
#include "image/image.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <vector>

using namespace strata;

namespace {

// The whole-set formula, straight from the pixels: sqrt(sum of squared RGB differences over every
// frame / number of RGB values), and the largest RGB difference.
void wholeSet(const std::vector<Image>& a, const std::vector<Image>& b, double& rmse, double& maxAbs) {
    double sum = 0.0;
    std::size_t n = 0;
    maxAbs = 0.0;
    for (std::size_t f = 0; f < a.size(); ++f)
        for (std::size_t i = 0; i < a[f].rgba.size(); ++i) {
            if (i % 4 == 3) continue;  // alpha is not compared
            double d = double(a[f].rgba[i]) - double(b[f].rgba[i]);
            sum += d * d;
            maxAbs = std::max(maxAbs, std::abs(d));
            ++n;
        }
    rmse = std::sqrt(sum / double(n));
}

}  // namespace

TEST_CASE("error accumulator: frames one at a time equal the whole set, closed form") {
    // Frame 0: every red differs by 1/8. Frame 1: one green differs by 1/2, every alpha by 1 (ignored).
    // Frame 2 (another size): identical. Sum of squares 8/64 + 1/4 = 3/8 over (8 + 8 + 4) * 3 = 60 values.
    Image a0(4, 2), b0(4, 2), a1(4, 2), b1(4, 2), a2(2, 2), b2(2, 2);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 4; ++x) {
            a0.set(x, y, {0.5f, 0.25f, 0.0f, 1.0f});
            b0.set(x, y, {0.375f, 0.25f, 0.0f, 1.0f});
            a1.set(x, y, {0.0f, 0.0f, 0.0f, 1.0f});
            b1.set(x, y, {0.0f, 0.0f, 0.0f, 0.0f});
        }
    b1.set(3, 1, {0.0f, 0.5f, 0.0f, 0.0f});
    ErrorAccumulator acc;
    CHECK(acc.rmse() == 0.0);
    CHECK(acc.psnr() == 100.0);
    acc.add(a0, b0);
    CHECK(acc.rmse() == doctest::Approx(std::sqrt(0.125 / 24.0)).epsilon(1e-12));  // red only: 1/3 of the values
    acc.add(a1, b1);
    acc.add(a2, b2);
    CHECK(acc.channels() == 60);
    CHECK(acc.rmse() == doctest::Approx(std::sqrt(0.375 / 60.0)).epsilon(1e-12));
    CHECK(acc.maxAbsError() == 0.5);
    CHECK(acc.psnr() == doctest::Approx(20.0 * std::log10(1.0 / std::sqrt(0.375 / 60.0))).epsilon(1e-12));
    // Not the mean of the per-frame RMSEs.
    CHECK(std::abs(acc.rmse() - (std::sqrt(0.125 / 24.0) + std::sqrt(0.25 / 24.0)) / 3.0) > 1e-3);
}

TEST_CASE("error accumulator: many irregular frames equal the whole set") {
    std::vector<Image> a, b;
    unsigned state = 12345u;
    auto next = [&] {
        state = state * 1664525u + 1013904223u;
        return float(state >> 8) / float(1u << 24);
    };
    for (int f = 0; f < 7; ++f) {
        int w = 3 + f, h = 5 - f % 3;
        Image x(w, h), y(w, h);
        for (auto& v : x.rgba) v = next();
        for (std::size_t i = 0; i < y.rgba.size(); ++i) y.rgba[i] = f == 3 ? x.rgba[i] : x.rgba[i] + 0.2f * (next() - 0.5f) * float(f);
        a.push_back(x);
        b.push_back(y);
    }
    ErrorAccumulator acc;
    for (std::size_t f = 0; f < a.size(); ++f) acc.add(a[f], b[f]);
    double rmse = 0.0, maxAbs = 0.0;
    wholeSet(a, b, rmse, maxAbs);
    REQUIRE(rmse > 0.0);
    CHECK(acc.rmse() == doctest::Approx(rmse).epsilon(1e-9));
    CHECK(acc.maxAbsError() == doctest::Approx(maxAbs).epsilon(1e-6));
}
