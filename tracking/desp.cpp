#include "tracking/desp.hpp"

#include <algorithm>
#include <cmath>

namespace strata::tracking {

void DespPredictor::reset() {
    have_ = false;
    period_ = options_.samplePeriod;
    periodSamples_ = 0;
}

void DespPredictor::update(const PoseSample& sample) {
    if (!have_) {
        s1_ = s2_ = sample.p;
        q1_ = q2_ = safeNormalized(sample.q);
        lastT_ = sample.t;
        period_ = options_.samplePeriod;
        have_ = true;
        return;
    }
    const double dt = sample.t - lastT_;
    if (dt <= 0.0) return;  // duplicate (alpha_eff = 0) or out of order
    if (options_.samplePeriod <= 0.0) {
        // Running mean of dt over the first samples, then a slow average; gaps excluded so a
        // dropout does not stretch the period (which would shrink tau and under-predict).
        if (period_ <= 0.0) {
            period_ = dt;
            periodSamples_ = 1;
        } else if (dt < 3.0 * period_) {
            periodSamples_ = std::min(periodSamples_ + 1, 100);
            period_ += (dt - period_) / periodSamples_;
        }
    }
    const double steps = period_ > 0.0 ? dt / period_ : 1.0;
    const double a = 1.0 - std::pow(1.0 - options_.positionAlpha, steps);
    s1_ = a * sample.p + (1.0 - a) * s1_;
    s2_ = a * s1_ + (1.0 - a) * s2_;
    const double b = 1.0 - std::pow(1.0 - options_.orientationAlpha, steps);
    q1_ = slerpExtrapolate(q1_, sample.q, b);
    q2_ = slerpExtrapolate(q2_, q1_, b);
    lastT_ = sample.t;
}

PoseSample DespPredictor::predict(double time) const {
    if (!have_) return PoseSample{time, Eigen::Vector3d::Zero(), Eigen::Quaterniond::Identity()};
    const double tau = period_ > 0.0 ? (time - lastT_) / period_ : 0.0;
    const double kp = options_.positionAlpha * tau / (1.0 - options_.positionAlpha);
    const double kq = options_.orientationAlpha * tau / (1.0 - options_.orientationAlpha);
    const Eigen::Vector3d p = (2.0 + kp) * s1_ - (1.0 + kp) * s2_;
    return PoseSample{time, p, slerpExtrapolate(q2_, q1_, 2.0 + kq)};
}

}  // namespace strata::tracking
