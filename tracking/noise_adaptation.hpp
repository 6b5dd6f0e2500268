#pragma once
// Noise levels learnt from the stream as it runs, so the Kalman predictor needs no per-trace
// tuning (KalmanOptions::adaptive).
//
// Measurement noise, from the measurements alone: a quadratic through the three previous
// samples (orientations as rotation vectors relative to the new one), extrapolated to it (Lagrange weights l_i for the actual, irregular times),
// misses it by e = sum l_i n_i - n_new + (motion the quadratic cannot follow). With white noise
// of variance sigma^2 per axis, e has variance sigma^2 (1 + sum l_i^2) per axis (20 sigma^2 at
// a uniform rate). The motion term is jerk * dt^3, small against the noise at tracker rates
// except at the onset of fast turns, so sigma^2 is a running median of e^2 / (1 + sum l^2)
// (a median shrugs those off; a mean would not): a multiplicative stochastic-approximation
// quantile tracker, O(1) per sample. Keeping this estimate apart from the filter matters:
// estimating R from the filter's own innovations couples it to the process noise (Sage-Husa's
// joint estimate is not identifiable from lag-0 innovations and drifts).
//
// Process noise, from the innovations given that R (covariance matching, Mehra 1972; the
// fading-memory form of Sage & Husa 1969): the normalised innovation squared
// NIS = r^T S^-1 r has mean m (the measured dimension) when the filter's Q is right. Its
// exponentially weighted mean over `window` seconds (the forgetting factor, per actual dt) steers
// the log of a scale on the process noise density: too large -> the model is lagging the head,
// raise Q; too small -> the model trusts noise, lower it. The scale is bounded to
// [minScale, maxScale] times the base density so one outlier cannot run it away and a still
// head does not freeze the filter.
#include "tracking/pose.hpp"

namespace strata::tracking {

// Running median of one pose part's per-axis noise variance (see above).
class NoiseMedian {
public:
    // One residual e (3 axes) whose noise part has variance gain2 * sigma^2 per axis.
    void add(const Eigen::Vector3d& e, double gain2);
    void reset() { median_ = 0.0, count_ = 0; }
    int count() const { return count_; }
    // sigma^2 per axis (0 before the first residual).
    double variance() const;

private:
    double median_ = 0.0;  // of e^2 / (3 gain2), whose median is 0.7887 sigma^2 (chi^2_3 / 3)
    int count_ = 0;
};

class MeasurementNoiseEstimator {
public:
    // Samples in time order; a duplicate time is skipped, and a gap (the four samples spanning
    // more than maxSpan seconds) starts over, because across it the motion term dominates.
    void add(const PoseSample& sample);
    void reset();
    // Standard deviations per axis (m, rad); `fallback` until minSamples residuals are in.
    double positionSigma(double fallback) const;
    double orientationSigma(double fallback) const;
    int residuals() const { return orientation_.count(); }

    static constexpr double maxSpan = 0.1;
    static constexpr int minSamples = 20;

private:
    PoseSample last_[3];  // oldest first
    int history_ = 0;
    NoiseMedian position_, orientation_;
};

struct ProcessNoiseAdaptation {
    // Chosen on synthetic.hpp's motion (seeds 1-3) and checked on activity_motion.hpp's: the
    // error is flat within ~2 % for windows of 0.05-0.2 s; a gain of 3 (the scale following
    // single turns) is 5-15 % worse everywhere: the scale should track the kind of motion, not
    // each turn, which the filter's own covariance already does.
    double window = 0.1;         // s, the innovation averaging (forgetting) time
    double gain = 0.3;           // d log(scale) per unit of log(mean NIS / m) per window
    double minScale = 0.02, maxScale = 50.0;
};

class ProcessNoiseScale {
public:
    explicit ProcessNoiseScale(const ProcessNoiseAdaptation& options = {}) : options_(options) {}
    // One innovation: its normalised square and dimension, and the time since the last one.
    void add(double nis, int dimension, double dt);
    void reset() { logScale_ = 0.0, meanNis_ = -1.0; }
    double scale() const;
    double meanNis() const { return meanNis_; }

private:
    ProcessNoiseAdaptation options_;
    double logScale_ = 0.0;
    double meanNis_ = -1.0;  // < 0 until the first innovation
};

}  // namespace strata::tracking
