#pragma once
// Pose predictors behind one interface, and the two simple baselines.
//
// A predictor is fed samples in time order and extrapolates the pose to a future (display)
// time. Every predictor accepts the same awkward streams, because real trackers produce them:
//  - irregular dt and missing samples: the actual dt between samples is used;
//  - duplicate timestamps (dt = 0): the newer sample replaces / refines the latest one, and
//    no rate is ever computed from a zero dt (no division by zero, no NaN);
//  - samples older than the latest one are ignored (out-of-order delivery);
//  - q and -q in consecutive samples: all differences go through quatLog, which takes the
//    shorter arc, so a sign flip is no motion;
//  - before the first sample predict() returns the identity pose at the requested time.
#include "tracking/pose.hpp"

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace strata::tracking {

class Predictor {
public:
    virtual ~Predictor() = default;
    virtual void update(const PoseSample& sample) = 0;
    // Pose expected at `time` (usually >= the latest sample's time; earlier times are
    // extrapolated backwards with the same model).
    virtual PoseSample predict(double time) const = 0;
    virtual std::string_view name() const = 0;
    // What the predictor has adapted to, in one short line for panels and logs; empty when it
    // has nothing that changes with the stream.
    virtual std::string describeState() const { return {}; }
    virtual void reset() = 0;
    virtual std::unique_ptr<Predictor> clone() const = 0;
};

// `none`: the latest sample, unchanged (what a renderer without prediction shows).
class LatestSamplePredictor final : public Predictor {
public:
    void update(const PoseSample& sample) override;
    PoseSample predict(double time) const override;
    std::string_view name() const override { return "none"; }
    void reset() override { have_ = false; }
    std::unique_ptr<Predictor> clone() const override { return std::make_unique<LatestSamplePredictor>(*this); }

private:
    PoseSample last_;
    bool have_ = false;
};

// `cv`: constant velocity from finite differences of the last two samples with distinct
// times: v = dp/dt and the world-frame angular velocity w = log(q1 q0^-1)/dt; extrapolates
// p + v*tau and exp(w*tau) q. No smoothing, so sensor noise is amplified by tau/dt.
class ConstantVelocityPredictor final : public Predictor {
public:
    void update(const PoseSample& sample) override;
    PoseSample predict(double time) const override;
    std::string_view name() const override { return "cv"; }
    void reset() override { count_ = 0; }
    std::unique_ptr<Predictor> clone() const override { return std::make_unique<ConstantVelocityPredictor>(*this); }

private:
    PoseSample prev_, last_;
    int count_ = 0;  // distinct-time samples seen, saturating at 2
};

// Predictor names the factory knows, in table order: none, cv, desp, kalman (constant-
// acceleration models), kalman-cv (constant-velocity models).
const std::vector<std::string>& predictorNames();
// Default-configured predictor by name; throws std::invalid_argument for an unknown name.
std::unique_ptr<Predictor> makePredictor(std::string_view name);

}  // namespace strata::tracking
