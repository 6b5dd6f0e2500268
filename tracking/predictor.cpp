#include "tracking/predictor.hpp"

#include "tracking/desp.hpp"
#include "tracking/kalman.hpp"

#include <stdexcept>

namespace strata::tracking {

void LatestSamplePredictor::update(const PoseSample& sample) {
    if (have_ && sample.t < last_.t) return;  // out of order: keep the newer one
    last_ = sample;
    have_ = true;
}

PoseSample LatestSamplePredictor::predict(double time) const {
    if (!have_) return PoseSample{time, Eigen::Vector3d::Zero(), Eigen::Quaterniond::Identity()};
    return PoseSample{time, last_.p, last_.q};
}

void ConstantVelocityPredictor::update(const PoseSample& sample) {
    if (count_ > 0 && sample.t < last_.t) return;
    if (count_ > 0 && sample.t == last_.t) {  // duplicate time: newer value, no rate from dt = 0
        last_ = sample;
        return;
    }
    prev_ = last_;
    last_ = sample;
    if (count_ < 2) ++count_;
}

PoseSample ConstantVelocityPredictor::predict(double time) const {
    if (count_ == 0) return PoseSample{time, Eigen::Vector3d::Zero(), Eigen::Quaterniond::Identity()};
    if (count_ == 1) return PoseSample{time, last_.p, last_.q};
    const double dt = last_.t - prev_.t;  // > 0 by construction
    const double tau = time - last_.t;
    const Eigen::Vector3d v = (last_.p - prev_.p) / dt;
    const Eigen::Vector3d w = worldDelta(prev_.q, last_.q) / dt;
    return PoseSample{time, last_.p + v * tau, safeNormalized(quatExp(w * tau) * last_.q)};
}

const std::vector<std::string>& predictorNames() {
    static const std::vector<std::string> names = {"none", "cv", "desp", "kalman", "kalman-fixed", "kalman-cv"};
    return names;
}

std::unique_ptr<Predictor> makePredictor(std::string_view name) {
    if (name == "none") return std::make_unique<LatestSamplePredictor>();
    if (name == "cv") return std::make_unique<ConstantVelocityPredictor>();
    if (name == "desp") return std::make_unique<DespPredictor>();
    if (name == "kalman" || name == "kalman-fixed") {
        // Constant-acceleration models for both, the better of the two on head turns (min-jerk
        // turns accelerate throughout; a CV model lags each turn's onset). `kalman` adapts its
        // noise to the stream; `kalman-fixed` keeps the densities tuned on synthetic.hpp's motion.
        KalmanOptions o;
        o.positionModel = MotionModel::ConstantAcceleration;
        o.orientationModel = MotionModel::ConstantAcceleration;
        if (name == "kalman") {
            o.adaptive = true;
            // Chosen by a sweep of 0.03-0.2 s on synthetic.hpp's motion (seeds 1-3): 0.03-0.05 s
            // are within 1 % of each other there and on activity_motion.hpp's walk and scan.
            o.accelerationDecay = 0.04;
        }
        return std::make_unique<KalmanPredictor>(o, std::string(name));
    }
    if (name == "kalman-cv") return std::make_unique<KalmanPredictor>(KalmanOptions{}, std::string("kalman-cv"));
    std::string known;
    for (const auto& n : predictorNames()) known += (known.empty() ? "" : ", ") + n;
    throw std::invalid_argument("unknown predictor `" + std::string(name) + "` (known: " + known + ")");
}

}  // namespace strata::tracking
