#include "tracking/noise_adaptation.hpp"

#include <algorithm>
#include <cmath>

namespace strata::tracking {
namespace {

constexpr double kChi2Over3Median = 0.78870;  // median of chi^2 with 3 degrees of freedom, / 3
constexpr double kMinMedianStep = 0.02;       // log step of the running median once settled

}  // namespace

void NoiseMedian::add(const Eigen::Vector3d& e, double gain2) {
    const double x = e.squaredNorm() / (3.0 * gain2);
    if (!std::isfinite(x)) return;
    ++count_;
    if (count_ == 1) {
        median_ = std::max(x, 1e-300);
        return;
    }
    // Multiplicative steps up or down settle where half the values lie above: the median, on a
    // log scale (the noise level spans decades). Larger steps at first, 1/n, to start fast.
    const double step = std::max(kMinMedianStep, 2.0 / double(count_));
    median_ *= std::exp(x > median_ ? step : -step);
}

double NoiseMedian::variance() const { return count_ ? median_ / kChi2Over3Median : 0.0; }

void MeasurementNoiseEstimator::reset() {
    history_ = 0;
    position_.reset();
    orientation_.reset();
}

void MeasurementNoiseEstimator::add(const PoseSample& s) {
    if (history_ > 0) {
        const double dt = s.t - last_[history_ - 1].t;
        if (dt <= 0.0) return;  // duplicate or out of order: no new information about the noise
        if (history_ == 3 && s.t - last_[0].t > maxSpan) history_ = 0;
    }
    if (history_ == 3) {
        // Lagrange weights of the quadratic through samples 0, 1, 2 evaluated at s.t.
        const double t0 = last_[0].t, t1 = last_[1].t, t2 = last_[2].t, t = s.t;
        const double l0 = (t - t1) * (t - t2) / ((t0 - t1) * (t0 - t2));
        const double l1 = (t - t0) * (t - t2) / ((t1 - t0) * (t1 - t2));
        const double l2 = (t - t0) * (t - t1) / ((t2 - t0) * (t2 - t1));
        const double gain2 = 1.0 + l0 * l0 + l1 * l1 + l2 * l2;
        // Relative to the new sample, which is then 0: e = 0 - sum l_i v_i.
        Eigen::Vector3d ep = Eigen::Vector3d::Zero(), eq = Eigen::Vector3d::Zero();
        const double l[3] = {l0, l1, l2};
        for (int i = 0; i < 3; ++i) {
            ep -= l[i] * (last_[i].p - s.p);
            eq -= l[i] * worldDelta(s.q, last_[i].q);
        }
        if (std::isfinite(gain2)) {
            position_.add(ep, gain2);
            orientation_.add(eq, gain2);
        }
        last_[0] = last_[1];
        last_[1] = last_[2];
        last_[2] = s;
    } else {
        last_[history_++] = s;
    }
}

double MeasurementNoiseEstimator::positionSigma(double fallback) const {
    return position_.count() >= minSamples ? std::sqrt(position_.variance()) : fallback;
}

double MeasurementNoiseEstimator::orientationSigma(double fallback) const {
    return orientation_.count() >= minSamples ? std::sqrt(orientation_.variance()) : fallback;
}

void ProcessNoiseScale::add(double nis, int dimension, double dt) {
    if (!std::isfinite(nis) || dt <= 0.0) return;
    const double m = double(dimension);
    nis = std::min(nis, 100.0 * m);  // one glitch moves the scale by a bounded step
    const double w = 1.0 - std::exp(-dt / options_.window);  // forgetting per actual dt
    meanNis_ = meanNis_ < 0.0 ? nis : meanNis_ + w * (nis - meanNis_);
    // Integral action on log(mean NIS / m): at rest only when the innovations match S.
    logScale_ += options_.gain * w * std::log(std::max(meanNis_, 1e-6) / m);
    logScale_ = std::clamp(logScale_, std::log(options_.minScale), std::log(options_.maxScale));
}

double ProcessNoiseScale::scale() const { return std::exp(logScale_); }

}  // namespace strata::tracking
