// The adaptive Kalman predictor (KalmanOptions::adaptive, tracking/noise_adaptation.hpp): the
// issue-13 aims on both synthetic generators, the noise it learns, and the estimators alone.
//
// Tuning used seeds 1-3 of synthetic.hpp's seated motion (and looked at walk/scan seeds 1-6);
// the aims are checked on seeds 11-13, which no choice of a constant looked at.
#include "tracking/activity_motion.hpp"
#include "tracking/kalman.hpp"
#include "tracking/synthetic.hpp"
#include "tracking/two_step.hpp"

#include <doctest/doctest.h>

#include <random>
#include <string>

using namespace strata::tracking;

namespace {

double meanDeg(const char* predictor, const SyntheticTraces& tr) {
    const Intrinsics k = Intrinsics::fromFov(1920, 1080, 90.0);
    const TwoStepConfig c;  // 50 ms latency, 5 ms re-read, 90 Hz display
    return summarize(simulateTwoStep(*makePredictor(predictor), tr.measured, tr.truth, c), Deflect::None, k).meanDeg;
}

SyntheticTraces seated(std::uint64_t seed, double noiseDeg = 0.02) {
    HeadMotionParams p;
    p.duration = 30.0;
    p.seed = seed;
    p.noiseDeg = noiseDeg;
    return generateHeadMotion(p);
}

SyntheticTraces activity(Activity a, std::uint64_t seed) {
    ActivityParams p;
    p.activity = a;
    p.duration = 30.0;
    p.seed = seed;
    return generateActivityMotion(p);
}

void checkAims(const SyntheticTraces& tr) {
    const double none = meanDeg("none", tr), cv = meanDeg("cv", tr), desp = meanDeg("desp", tr);
    const double kalman = meanDeg("kalman", tr);
    CAPTURE(none);
    CAPTURE(cv);
    CAPTURE(desp);
    CAPTURE(kalman);
    // Measured on seeds 11-13: none / kalman is 4.0-5.3 (seated), 3.6-3.8 (walk), 4.5-4.6 (scan);
    // kalman is 7-17 % below the better of cv and desp.
    CHECK(kalman <= none / 3.0);
    CHECK(kalman < 0.95 * cv);
    CHECK(kalman < 0.95 * desp);
}

}  // namespace

TEST_CASE("adaptive kalman: a third of no prediction and below cv and desp at 50 ms, seated motion") {
    for (std::uint64_t seed : {11, 12, 13}) {
        CAPTURE(seed);
        checkAims(seated(seed));
    }
}

TEST_CASE("adaptive kalman: the same aims on the walk and the scan, which nothing was tuned on") {
    for (Activity a : {Activity::Walk, Activity::Scan})
        for (std::uint64_t seed : {11, 12, 13}) {
            CAPTURE(activityName(a));
            CAPTURE(seed);
            checkAims(activity(a, seed));
        }
}

TEST_CASE("adaptive kalman beats the fixed tuning where the fixed tuning is wrong") {
    // The walk (noise 0.03 deg, gentle motion) and a sensor five times noisier than the one the
    // fixed densities were tuned for: fixed 0.79 / 2.2 deg against adaptive 0.60 / 1.3 deg.
    const SyntheticTraces walk = activity(Activity::Walk, 11);
    CHECK(meanDeg("kalman", walk) < 0.85 * meanDeg("kalman-fixed", walk));
    const SyntheticTraces noisy = seated(11, 0.1);
    CHECK(meanDeg("kalman", noisy) < 0.7 * meanDeg("kalman-fixed", noisy));
}

TEST_CASE("adaptive kalman learns the sensor's noise and the kind of motion") {
    struct Case {
        const char* name;
        SyntheticTraces traces;
        double noiseDeg, noiseMm;
    };
    const Case cases[] = {{"seated", seated(12), 0.02, 0.2},
                          {"seated noisy", seated(12, 0.1), 0.1, 0.2},
                          {"walk", activity(Activity::Walk, 12), 0.03, 0.3},
                          {"scan", activity(Activity::Scan, 12), 0.03, 0.3}};
    double scale[4];
    for (int i = 0; i < 4; ++i) {
        const Case& c = cases[i];
        const std::string name = c.name;
        CAPTURE(name);
        auto p = makePredictor("kalman");
        const auto& kalman = dynamic_cast<const KalmanPredictor&>(*p);
        double nisSum = 0.0;
        for (const auto& s : c.traces.measured) {
            p->update(s);
            nisSum += kalman.noiseLevels().orientationNis;
        }
        const KalmanNoiseLevels n = kalman.noiseLevels();
        // Within 10 %: the head's own jerk leaks a little into the quadratic's residual.
        CHECK(radToDeg(n.orientationSigma) == doctest::Approx(c.noiseDeg).epsilon(0.10));
        CHECK(n.positionSigma * 1e3 == doctest::Approx(c.noiseMm).epsilon(0.10));
        // Matched innovations: NIS per dimension near 1 on average over the trace (measured
        // 1.00-1.10, and 1.30 on the scan, whose turn onsets outrun any bounded adaptation; the
        // 0.1 s running mean itself swings from ~0.3 in fixations to ~3 at turn onsets).
        const double meanNis = nisSum / double(c.traces.measured.size());
        CHECK(meanNis > 0.8);
        CHECK(meanNis < 1.5);
        CHECK(p->describeState().find("noise") != std::string::npos);
        scale[i] = n.orientationScale;
    }
    // The walk's slow sweeps need less process noise than the scan's fast turns.
    CHECK(scale[2] < 0.5);
    CHECK(scale[3] > 2.0 * scale[2]);
    // The fixed filter has nothing to report.
    CHECK(makePredictor("kalman-fixed")->describeState().empty());
}

TEST_CASE("measurement noise estimator: white noise on a quadratic at irregular times") {
    // A quadratic is what the estimator's extrapolation cancels exactly, so the estimate is the
    // noise alone: within 5 % of sigma after 3000 samples with 30 % timing jitter and dropouts.
    std::mt19937_64 rng(5);
    std::normal_distribution<double> n(0.0, 1.0);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double sigmaRad = degToRad(0.05), sigmaM = 1e-3;
    MeasurementNoiseEstimator e;
    double t = 0.0;
    for (int i = 0; i < 3000; ++i) {
        t += (1.0 + 0.3 * (u(rng) - 0.5)) / 100.0 * (u(rng) < 0.05 ? 2.0 : 1.0);
        const Eigen::Vector3d truthRot = Eigen::Vector3d(0.3, 1.0, -0.2) * (0.5 * t + 0.8 * t * t);
        const Eigen::Vector3d truthPos = Eigen::Vector3d(1.0, 0.2, -0.5) * (0.7 * t - 0.3 * t * t);
        e.add(PoseSample{t, truthPos + sigmaM * Eigen::Vector3d(n(rng), n(rng), n(rng)),
                         quatExp(sigmaRad * Eigen::Vector3d(n(rng), n(rng), n(rng))) * quatExp(truthRot)});
        if (i % 7 == 0) e.add(PoseSample{t, Eigen::Vector3d::Zero(), Eigen::Quaterniond::Identity()});  // dt = 0: skipped
    }
    CHECK(e.orientationSigma(0.0) == doctest::Approx(sigmaRad).epsilon(0.05));
    CHECK(e.positionSigma(0.0) == doctest::Approx(sigmaM).epsilon(0.05));
    // Before minSamples residuals the fallback is returned.
    MeasurementNoiseEstimator fresh;
    CHECK(fresh.orientationSigma(0.123) == 0.123);
}

TEST_CASE("process noise scale: up when innovations exceed S, down when below, within bounds") {
    ProcessNoiseAdaptation o;
    ProcessNoiseScale s(o);
    for (int i = 0; i < 2000; ++i) s.add(3.0 * 10.0, 3, 0.01);  // NIS 10x what S predicts
    CHECK(s.scale() == doctest::Approx(o.maxScale));
    for (int i = 0; i < 4000; ++i) s.add(3.0 * 0.01, 3, 0.01);
    CHECK(s.scale() == doctest::Approx(o.minScale));
    // Matched innovations leave it where it is; dt = 0 and NaN change nothing.
    ProcessNoiseScale m(o);
    for (int i = 0; i < 1000; ++i) m.add(3.0, 3, 0.01);
    CHECK(m.scale() == doctest::Approx(1.0));
    m.add(1e9, 3, 0.0);
    m.add(std::nan(""), 3, 0.01);
    CHECK(m.scale() == doctest::Approx(1.0));
}
