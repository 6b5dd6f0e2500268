#pragma once
// The synthetic generators' randomness: std::mt19937_64 (its output is specified by the
// standard) with hand-written uniform and Box-Muller normal draws, because the standard
// library's distributions differ between implementations. A seed therefore gives the same
// traces with any standard library.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>

namespace strata::tracking {

inline constexpr double kTwoPi = 6.283185307179586476925;

class SeededRng {
public:
    explicit SeededRng(std::uint64_t seed) : engine_(seed) {}
    double uniform() { return double(engine_() >> 11) * 0x1.0p-53; }  // [0, 1), 53 bits
    double uniform(double a, double b) { return a + (b - a) * uniform(); }
    double normal() {  // Box-Muller; the spare draw is dropped to keep the code obvious
        const double u1 = 1.0 - uniform();  // (0, 1]
        const double u2 = uniform();
        return std::sqrt(-2.0 * std::log(u1)) * std::cos(kTwoPi * u2);
    }

private:
    std::mt19937_64 engine_;
};

// Minimum-jerk position profile s(u) = 10u^3 - 15u^4 + 6u^5 on u in [0, 1] (Flash & Hogan
// 1985): zero velocity and acceleration at both ends, peak speed 1.875 at u = 1/2.
inline double minimumJerk(double u) {
    u = std::clamp(u, 0.0, 1.0);
    return u * u * u * (10.0 + u * (-15.0 + 6.0 * u));
}

}  // namespace strata::tracking
