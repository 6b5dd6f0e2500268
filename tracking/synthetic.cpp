#include "tracking/synthetic.hpp"

#include "tracking/seeded_rng.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace strata::tracking {

HeadMotionModel::HeadMotionModel(const HeadMotionParams& params) : params_(params) {
    SeededRng rng(params.seed);
    for (int a = 0; a < 3; ++a) {
        sway_[a] = Wave{params.swayDeg * (a == 2 ? 1.5 : 1.0), rng.uniform(0.1, 0.3), rng.uniform(0.0, kTwoPi)};
        swayPos_[a] = Wave{params.swayMm * 1e-3 * (a == 1 ? 0.5 : 1.0), rng.uniform(0.1, 0.3), rng.uniform(0.0, kTwoPi)};
        for (auto& w : tremor_[a])
            w = Wave{params.tremorDeg, rng.uniform(params.tremorHzMin, params.tremorHzMax), rng.uniform(0.0, kTwoPi)};
    }
    // Turn schedule: pause, turn, pause, turn ... until the end of the trace.
    double t = rng.uniform(params.pauseMin, params.pauseMax) * 0.5;
    double yaw = 0.0, pitch = 0.0;
    while (t < params.duration) {
        double ty = 0.0, tp = 0.0, amplitude = 0.0;
        for (int attempt = 0; attempt < 32; ++attempt) {  // a target far enough to be a turn
            ty = rng.uniform(-params.yawRange, params.yawRange);
            tp = rng.uniform(-params.pitchRange, params.pitchRange);
            amplitude = std::hypot(ty - yaw, tp - pitch);
            if (amplitude >= params.minTurnDeg) break;
        }
        const double peak = std::clamp(80.0 + 3.5 * amplitude + 20.0 * rng.normal(), params.minPeakDegPerSec,
                                       params.maxPeakDegPerSec);
        const double duration = std::max(1e-3, 1.875 * amplitude / peak);
        turns_.push_back(Turn{t, duration, ty - yaw, tp - pitch});
        yaw = ty;
        pitch = tp;
        t += duration + rng.uniform(params.pauseMin, params.pauseMax);
    }
}

PoseSample HeadMotionModel::at(double t) const {
    double angle[3] = {0.0, 0.0, 0.0};  // yaw, pitch, roll in degrees
    for (const auto& turn : turns_) {
        if (t <= turn.start) break;  // turns are in time order
        const double s = minimumJerk((t - turn.start) / turn.duration);
        angle[0] += turn.dYaw * s;
        angle[1] += turn.dPitch * s;
    }
    for (int a = 0; a < 3; ++a) {
        angle[a] += sway_[a].amplitude * std::sin(kTwoPi * sway_[a].hz * t + sway_[a].phase);
        for (const auto& w : tremor_[a]) angle[a] += w.amplitude * std::sin(kTwoPi * w.hz * t + w.phase);
    }
    const Eigen::Quaterniond q = Eigen::AngleAxisd(degToRad(angle[0]), Eigen::Vector3d::UnitY()) *
                                 Eigen::AngleAxisd(degToRad(angle[1]), Eigen::Vector3d::UnitX()) *
                                 Eigen::AngleAxisd(degToRad(angle[2]), Eigen::Vector3d::UnitZ());
    const Eigen::Vector3d pivot(0.0, 1.2, 0.0);
    const Eigen::Vector3d eyesFromPivot(0.0, 0.10, -0.08);  // up and forward (-Z) of the neck
    Eigen::Vector3d p = pivot + q * eyesFromPivot;
    for (int a = 0; a < 3; ++a)
        p[a] += swayPos_[a].amplitude * std::sin(kTwoPi * swayPos_[a].hz * t + swayPos_[a].phase);
    return PoseSample{t, p, q.normalized()};
}

std::string HeadMotionModel::describe() const {
    const auto& p = params_;
    char buf[512];
    std::snprintf(buf, sizeof buf,
                  "synthetic head motion: seed %llu, %.3g s, %zu turns at %g-%g deg/s peak, sway %g deg / %g mm, "
                  "tremor %g deg at %g-%g Hz, sensor %g Hz, noise %g deg / %g mm, jitter %g ms, drop %g",
                  static_cast<unsigned long long>(p.seed), p.duration, turns_.size(), p.minPeakDegPerSec,
                  p.maxPeakDegPerSec, p.swayDeg, p.swayMm, p.tremorDeg, p.tremorHzMin, p.tremorHzMax, p.sampleHz,
                  p.noiseDeg, p.noiseMm, p.jitterMs, p.dropProbability);
    return buf;
}

SyntheticTraces generateHeadMotion(const HeadMotionParams& params) {
    const HeadMotionModel model(params);
    SyntheticTraces out;
    out.truth = sampleModel(model, params.duration, params.truthHz);
    // Separate stream from the model's so changing the sensor leaves the motion unchanged.
    SeededRng rng(params.seed ^ 0x9e3779b97f4a7c15ull);
    const double noise = degToRad(params.noiseDeg);
    if (params.sampleHz > 0.0) {
        const auto n = static_cast<long long>(std::floor(params.duration * params.sampleHz));
        double previous = -1e300;
        for (long long i = 0; i <= n; ++i) {
            const double jitter = params.jitterMs * 1e-3 * rng.normal();
            const bool drop = rng.uniform() < params.dropProbability;
            const Eigen::Vector3d rotNoise(rng.normal(), rng.normal(), rng.normal());
            const Eigen::Vector3d posNoise(rng.normal(), rng.normal(), rng.normal());
            const bool flip = rng.uniform() < params.flipProbability;
            if (drop && i > 0) continue;
            // Keep time order: jitter may not reorder samples (a tracker stamps monotonically).
            const double t = std::clamp(double(i) / params.sampleHz + jitter, 0.0, params.duration);
            if (t < previous) continue;
            previous = t;
            PoseSample s = model.at(t);
            s.p += params.noiseMm * 1e-3 * posNoise;
            s.q = safeNormalized(quatExp(noise * rotNoise) * s.q);
            if (flip) s.q.coeffs() = -s.q.coeffs();
            out.measured.push_back(s);
        }
    }
    return out;
}

}  // namespace strata::tracking
