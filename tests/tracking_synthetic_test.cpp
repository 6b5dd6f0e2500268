// Synthetic head motion (the model's stated properties) and the two-step evaluation on it.
#include "test_paths.hpp"
#include "tracking/synthetic.hpp"
#include "tracking/trace_io.hpp"
#include "tracking/two_step.hpp"

#include <doctest/doctest.h>

#include <filesystem>

using namespace strata::tracking;

TEST_CASE("synthetic head motion: seeded, turns at 100-300 deg/s, sensor properties") {
    HeadMotionParams p;
    p.duration = 20.0;
    const SyntheticTraces a = generateHeadMotion(p);
    const SyntheticTraces b = generateHeadMotion(p);
    REQUIRE(a.measured.size() == b.measured.size());
    CHECK(a.measured.back().q.coeffs() == b.measured.back().q.coeffs());
    CHECK(a.truth.size() == std::size_t(20.0 * p.truthHz) + 1);
    // Dropouts: about 1 % missing of 2401 samples.
    CHECK(a.measured.size() < 2401);
    CHECK(a.measured.size() > 2300);

    double peak = 0.0;
    for (std::size_t i = 1; i < a.truth.size(); ++i)
        peak = std::max(peak, angleBetween(a.truth[i - 1].q, a.truth[i].q) * p.truthHz);
    // Turn peaks are clamped to 300 deg/s; sway and tremor add a few deg/s on top.
    CHECK(radToDeg(peak) > 150.0);
    CHECK(radToDeg(peak) < 320.0);

    // Noise: mean angle between measured and truth ~ 1.6 sigma (3-D Gaussian), no bias.
    double sum = 0.0;
    for (const auto& s : a.measured) sum += angleBetween(s.q, sampleAt(a.truth, s.t).q);
    const double mean = radToDeg(sum / double(a.measured.size()));
    CHECK(mean == doctest::Approx(1.596 * p.noiseDeg).epsilon(0.15));
}

TEST_CASE("two-step prediction on synthetic motion: kalman beats none, homography halves it") {
    HeadMotionParams p;
    p.duration = 20.0;
    p.seed = 42;
    const SyntheticTraces tr = generateHeadMotion(p);
    const Intrinsics k = Intrinsics::fromFov(1920, 1080, 90.0);
    const TwoStepConfig c;  // 50 ms latency, 5 ms re-read
    const auto none = simulateTwoStep(*makePredictor("none"), tr.measured, tr.truth, c);
    const auto kalman = simulateTwoStep(*makePredictor("kalman"), tr.measured, tr.truth, c);
    const double noneDeg = summarize(none, Deflect::None, k).meanDeg;
    const ErrorStats kal = summarize(kalman, Deflect::None, k);
    const ErrorStats kalH = summarize(kalman, Deflect::Homography, k);
    CHECK(kal.meanDeg < noneDeg / 3.0);
    CHECK(kalH.meanDeg < kal.meanDeg / 2.0);
    CHECK(kal.p95Deg <= kal.maxDeg);
    CHECK(kal.frames == none.size());
    CHECK(measureUpdateNs(*makePredictor("kalman"), tr.measured, 0.01) > 0.0);

    // Zero latency and zero re-read: `none` shows only the sample age and the noise.
    TwoStepConfig zero;
    zero.latency = zero.reread = 0.0;
    const double noneZero = summarize(simulateTwoStep(*makePredictor("none"), tr.measured, tr.truth, zero),
                                      Deflect::None, k).meanDeg;
    CHECK(noneZero < noneDeg / 3.0);
}

TEST_CASE("shipped example traces parse") {
    const std::filesystem::path dir = strata::test::sourceDir() / "scenes" / "traces";
    const Trace measured = readTrace((dir / "head-synthetic-measured.path").string());
    const Trace truth = readTrace((dir / "head-synthetic-truth.path").string());
    CHECK(measured.size() > 400);
    CHECK(truth.size() > 400);
}
