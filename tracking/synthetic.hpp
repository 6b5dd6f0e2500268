#pragma once
// Synthetic head motion for tests and demos: a seeded, documented model of a seated viewer
// looking around, with a noise-free truth and a measured (tracker-like) trace.
//
// Orientation q = Ry(yaw) Rx(pitch) Rz(roll) (yaw about world up, then pitch about the head's
// right axis, roll about the view axis), each angle the sum of
//  - head turns (gaze shifts): after a fixation pause (uniform in [pauseMin, pauseMax] s) the
//    head moves to a new target (yaw uniform in +-yawRange, pitch in +-pitchRange, at least
//    minTurnDeg away) along a minimum-jerk profile s(u) = 10u^3 - 15u^4 + 6u^5 (Flash & Hogan
//    1985; smooth velocity and acceleration, bell-shaped speed). The peak angular speed
//    follows a main-sequence-like rule, larger turns faster: v = 80 + 3.5 * amplitude(deg)
//    deg/s plus N(0, 20), clamped to [minPeakDegPerSec, maxPeakDegPerSec] (default 100-300);
//    the duration is then T = 1.875 * amplitude / v (the min-jerk peak speed is 1.875 A/T);
//  - sway: slow postural drift, sinusoids at 0.1-0.3 Hz of swayDeg amplitude (roll 1.5x);
//  - physiological tremor: two sinusoids per axis at random frequencies in
//    [tremorHzMin, tremorHzMax] (default 8-12 Hz) of tremorDeg amplitude (default 0.03 deg).
// Position: the eyes sit 10 cm above and 8 cm in front of a neck pivot at 1.2 m height, so
// turning the head moves them (as on a real neck), plus torso sway of swayMm at 0.1-0.3 Hz.
//
// Measured trace: sampled at sampleHz with timestamp jitter N(0, jitterMs), a fraction
// dropProbability of samples missing (dropouts), orientation noise exp(n) q with n ~ N(0,
// noiseDeg^2) per world axis (default 0.02 deg, typical of sensor-fused HMD
// orientation), position noise N(0, noiseMm^2) per axis, and optionally the
// quaternion sign flipped (q -> -q, the same rotation) with flipProbability.
// Truth trace: the model sampled at truthHz without noise, jitter or dropouts.
//
// Randomness: std::mt19937_64 (specified by the standard) with hand-written uniform and
// Box-Muller normal draws, so a seed gives the same traces with any standard library.
#include "tracking/pose.hpp"

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace strata::tracking {

struct HeadMotionParams {
    double duration = 10.0;  // s
    std::uint64_t seed = 1;
    double sampleHz = 120.0;
    double truthHz = 1000.0;
    double minPeakDegPerSec = 100.0, maxPeakDegPerSec = 300.0;
    double pauseMin = 0.15, pauseMax = 1.2;  // s
    double yawRange = 90.0, pitchRange = 30.0, minTurnDeg = 15.0;
    double swayDeg = 1.0, swayMm = 10.0;
    double tremorDeg = 0.03, tremorHzMin = 8.0, tremorHzMax = 12.0;
    double noiseDeg = 0.02, noiseMm = 0.2;  // fused-HMD-like jitter; 0.1 / 0.5 is "noisy"
    double jitterMs = 0.3, dropProbability = 0.01, flipProbability = 0.0;
};

class HeadMotionModel {
public:
    explicit HeadMotionModel(const HeadMotionParams& params);
    PoseSample at(double t) const;
    const HeadMotionParams& params() const { return params_; }
    // One line describing the model parameters (for file headers and command output).
    std::string describe() const;

private:
    struct Turn {
        double start, duration, dYaw, dPitch;  // degrees
    };
    struct Wave {
        double amplitude, hz, phase;
    };
    HeadMotionParams params_;
    std::vector<Turn> turns_;
    Wave sway_[3], swayPos_[3], tremor_[3][2];
};

struct SyntheticTraces {
    Trace truth, measured;
};

// The noise-free model (anything with `Pose at(double t) const`) sampled at `hz` over
// [0, duration]: both generators' truth traces. Empty when hz <= 0.
template <class Model>
Trace sampleModel(const Model& model, double duration, double hz) {
    Trace out;
    if (!(hz > 0.0)) return out;
    const auto n = static_cast<long long>(std::floor(duration * hz));
    out.reserve(std::size_t(n + 1));
    for (long long i = 0; i <= n; ++i) out.push_back(model.at(double(i) / hz));
    return out;
}

SyntheticTraces generateHeadMotion(const HeadMotionParams& params);

}  // namespace strata::tracking
