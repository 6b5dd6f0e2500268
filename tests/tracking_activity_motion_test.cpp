// The second synthetic generator (tracking/activity_motion.hpp): the properties its header states.
#include "tracking/activity_motion.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

using namespace strata::tracking;

namespace {

SyntheticTraces make(Activity a, double duration, std::uint64_t seed = 4) {
    ActivityParams p;
    p.activity = a;
    p.duration = duration;
    p.seed = seed;
    return generateActivityMotion(p);
}

double peakDegPerSec(const Trace& truth, double hz) {
    double peak = 0.0;
    for (std::size_t i = 1; i < truth.size(); ++i) peak = std::max(peak, angleBetween(truth[i - 1].q, truth[i].q) * hz);
    return radToDeg(peak);
}

}  // namespace

TEST_CASE("activity motion: seeded, named, and a different stream for each seed") {
    const SyntheticTraces a = make(Activity::Scan, 10.0), b = make(Activity::Scan, 10.0);
    REQUIRE(a.measured.size() == b.measured.size());
    CHECK(a.measured.back().q.coeffs() == b.measured.back().q.coeffs());
    CHECK(make(Activity::Scan, 10.0, 5).measured.back().q.coeffs() != a.measured.back().q.coeffs());
    CHECK(parseActivity("walk") == Activity::Walk);
    CHECK(activityName(Activity::Scan) == "scan");
    CHECK_THROWS_AS(parseActivity("run"), std::invalid_argument);
}

TEST_CASE("activity motion: walk moves at walking speed with a gait bob and slow turns") {
    const SyntheticTraces w = make(Activity::Walk, 30.0);
    // Speed 1.1-1.5 m/s along a path that turns: the straight-line distance is at most that.
    const Eigen::Vector3d d = w.truth.back().p - w.truth.front().p;
    double path = 0.0, minY = 1e9, maxY = -1e9;
    for (std::size_t i = 1; i < w.truth.size(); ++i) {
        const Eigen::Vector3d step = w.truth[i].p - w.truth[i - 1].p;
        path += std::hypot(step.x(), step.z());
        minY = std::min(minY, w.truth[i].p.y());
        maxY = std::max(maxY, w.truth[i].p.y());
    }
    CHECK(path / 30.0 > 1.1);
    CHECK(path / 30.0 < 1.6);  // the sideways sway adds a little
    CHECK(std::hypot(d.x(), d.z()) < path);
    // Vertical bob +-2 cm plus its harmonic at a third: peak to peak 4-6 cm.
    CHECK(maxY - minY > 0.035);
    CHECK(maxY - minY < 0.065);
    // Slow: sweeps and gait oscillations stay well under the scan's speeds.
    CHECK(peakDegPerSec(w.truth, 1000.0) < 150.0);
}

TEST_CASE("activity motion: scan turns fast, and the sensor drops samples in bursts") {
    const SyntheticTraces s = make(Activity::Scan, 30.0);
    const double peak = peakDegPerSec(s.truth, 1000.0);
    // Single shifts peak at 150-450 deg/s; overlapping ones add up.
    CHECK(peak > 200.0);
    CHECK(peak < 700.0);
    // 90 Hz: 2701 slots; bursts of 2-8 with probability 0.004 lose ~1.8 %.
    CHECK(s.measured.size() < 2701);
    CHECK(s.measured.size() > 2600);
    int longGaps = 0;
    for (std::size_t i = 1; i < s.measured.size(); ++i) longGaps += s.measured[i].t - s.measured[i - 1].t > 2.5 / 90.0;
    CHECK(longGaps > 3);  // runs of lost samples, not single ones
    // Orientation noise 0.03 deg per axis: the mean angle is ~1.6 sigma.
    double sum = 0.0;
    for (const auto& m : s.measured) sum += angleBetween(m.q, sampleAt(s.truth, m.t).q);
    CHECK(radToDeg(sum / double(s.measured.size())) == doctest::Approx(1.596 * 0.03).epsilon(0.15));
}
