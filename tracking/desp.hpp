#pragma once
// `desp`: LaViola's double exponential smoothing predictor ("Double Exponential Smoothing: An
// Alternative to Kalman Filter-Based Predictive Tracking", IPT/EGVE 2003).
//
// Position (per sample, smoothing weight alpha in (0, 1)):
//   S1 = alpha p + (1 - alpha) S1,     S2 = alpha S1 + (1 - alpha) S2
//   p(t + tau) = (2 + k) S1 - (1 + k) S2,   k = alpha tau / (1 - alpha)
// with tau in sample periods. Orientation uses LaViola's quaternion form, the same recursion
// with slerp: Sq1 = slerp(Sq1, q, alpha), Sq2 = slerp(Sq2, Sq1, alpha), and the prediction
// slerp(Sq2, Sq1, 2 + k) (extrapolating along the shorter arc).
//
// The paper assumes uniform sampling. For irregular streams the per-sample weight becomes
// alpha_eff = 1 - (1 - alpha)^(dt / period), which equals alpha at dt = period, decays a gap of
// n periods like n uniform steps, and is 0 for a duplicate timestamp (dt = 0: no change).
// The period is fixed by the options or estimated as a running mean of the observed dt with
// gaps (dt > 3 periods) excluded.
#include "tracking/predictor.hpp"

namespace strata::tracking {

struct DespOptions {
    // Smoothing weights per sample period, position and orientation separately (LaViola uses one;
    // the two signals differ in noise and motion). Chosen by a sweep on the synthetic head motion
    // at 120 Hz, 50 ms latency (strata track --synthetic): smaller lags on turns, larger passes
    // noise through (the trend term multiplies it by alpha/(1-alpha) tau).
    double positionAlpha = 0.6;
    double orientationAlpha = 0.8;
    double samplePeriod = 0.0;  // seconds; 0 = estimate from the stream
};

class DespPredictor final : public Predictor {
public:
    explicit DespPredictor(const DespOptions& options = {}) : options_(options) {}
    void update(const PoseSample& sample) override;
    PoseSample predict(double time) const override;
    std::string_view name() const override { return "desp"; }
    void reset() override;
    std::unique_ptr<Predictor> clone() const override { return std::make_unique<DespPredictor>(*this); }

    double period() const { return period_; }

private:
    DespOptions options_;
    Eigen::Vector3d s1_ = Eigen::Vector3d::Zero(), s2_ = Eigen::Vector3d::Zero();
    Eigen::Quaterniond q1_ = Eigen::Quaterniond::Identity(), q2_ = Eigen::Quaterniond::Identity();
    double lastT_ = 0.0;
    double period_ = 0.0;  // seconds, 0 until known
    int periodSamples_ = 0;
    bool have_ = false;
};

}  // namespace strata::tracking
