#include "tracking/activity_motion.hpp"

#include "tracking/seeded_rng.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace strata::tracking {
namespace {

constexpr double kTorsoLag = 0.6;  // s, scan: the torso's yaw follows the head's

double wave(double amplitude, double hz, double phase, double t) {
    return amplitude * std::sin(kTwoPi * hz * t + phase);
}

// Scan: the gaze shifts, their optional corrective turns and the overlaps (see the header).
void scheduleScan(SeededRng& rng, double duration, std::vector<double>& start, std::vector<double>& length,
                  std::vector<Eigen::Vector3d>& delta) {
    double t = rng.uniform(0.1, 0.4), yaw = 0.0, pitch = 0.0, roll = 0.0;
    auto add = [&](double begin, double amplitude, double peakDegPerSec, double dYaw, double dPitch) {
        const double dRoll = 0.1 * dYaw - roll;  // roll follows this shift's yaw, not all of them
        start.push_back(begin);
        length.push_back(std::max(1e-3, 1.875 * amplitude / peakDegPerSec));
        delta.emplace_back(dYaw, dPitch, dRoll);
        yaw += dYaw;
        pitch += dPitch;
        roll += dRoll;
        return length.back();
    };
    while (t < duration) {
        const double amplitude = rng.uniform(20.0, 120.0);
        double dYaw = amplitude * (rng.uniform() < 0.5 ? -1.0 : 1.0);
        if (std::abs(yaw + dYaw) > 150.0) dYaw = -dYaw;  // stay within reach of the torso
        double dPitch = amplitude * rng.uniform(-0.25, 0.25);
        if (std::abs(pitch + dPitch) > 35.0) dPitch = -dPitch;
        const double peak = std::clamp(120.0 + 2.8 * amplitude + 30.0 * rng.normal(), 150.0, 450.0);
        const double length = add(t, std::hypot(dYaw, dPitch), peak, dYaw, dPitch);
        const bool overlap = rng.uniform() < 1.0 / 3.0;
        const bool correct = amplitude > 40.0 && rng.uniform() < 0.4;
        if (overlap) {
            t += length * rng.uniform(0.55, 0.9);
            continue;
        }
        t += length;
        if (correct) {
            const double a = rng.uniform(2.0, 6.0), dir = rng.uniform(0.0, kTwoPi);
            t += rng.uniform(0.08, 0.2);
            t += add(t, a, rng.uniform(30.0, 60.0), a * std::cos(dir), a * std::sin(dir));
        }
        t += rng.uniform(0.08, 0.5);
    }
}

// Walk: straight stretches and slow min-jerk re-orientations of the body's heading.
void scheduleWalk(SeededRng& rng, double duration, std::vector<double>& start, std::vector<double>& length,
                  std::vector<Eigen::Vector3d>& delta) {
    double t = rng.uniform(1.0, 4.0);
    while (t < duration) {
        const double turn = rng.uniform(30.0, 120.0) * (rng.uniform() < 0.5 ? -1.0 : 1.0);
        start.push_back(t);
        length.push_back(rng.uniform(1.5, 3.5));
        delta.emplace_back(turn, 0.0, 0.0);
        t += length.back() + rng.uniform(1.0, 4.0);
    }
}

}  // namespace

std::string_view activityName(Activity activity) { return activity == Activity::Walk ? "walk" : "scan"; }

Activity parseActivity(std::string_view name) {
    if (name == "walk") return Activity::Walk;
    if (name == "scan") return Activity::Scan;
    throw std::invalid_argument("unknown activity `" + std::string(name) + "` (known: walk, scan)");
}

ActivityModel::ActivityModel(const ActivityParams& params) : params_(params) {
    SeededRng rng(params.seed);
    // Every draw happens whatever the activity, so the two share their slow components' seeds.
    for (auto& w : yawSweep_) w = Wave{rng.uniform(8.0, 25.0), rng.uniform(0.05, 0.35), rng.uniform(0.0, kTwoPi)};
    for (auto& w : pitchSweep_) w = Wave{rng.uniform(4.0, 10.0), rng.uniform(0.05, 0.25), rng.uniform(0.0, kTwoPi)};
    for (auto& w : swayPos_) w = Wave{0.015, rng.uniform(0.1, 0.3), rng.uniform(0.0, kTwoPi)};
    stepHz_ = rng.uniform(1.7, 2.1);
    stepModHz_ = rng.uniform(0.05, 0.15);
    stepModDepth_ = rng.uniform(0.02, 0.06);
    gaitPhase0_ = rng.uniform(0.0, kTwoPi);
    speed_ = rng.uniform(1.1, 1.5);
    const double heading0 = rng.uniform(-180.0, 180.0);

    std::vector<double> start, length;
    std::vector<Eigen::Vector3d> delta;
    if (params.activity == Activity::Scan) scheduleScan(rng, params.duration, start, length, delta);
    else scheduleWalk(rng, params.duration, start, length, delta);
    auto& shifts = params.activity == Activity::Scan ? headShifts_ : bodyTurns_;
    for (std::size_t i = 0; i < start.size(); ++i)
        shifts.push_back(Shift{start[i], length[i], {delta[i].x(), delta[i].y(), delta[i].z()}});
    // Overlapping shifts were pushed in start order, so the list stays sorted by start.

    // The slow state integrated at 1 kHz (explicit Euler; the step is 1/1000 of the fastest
    // time constant involved, 0.6 s, and the body turns take seconds).
    const auto n = static_cast<std::size_t>(std::ceil(params.duration * gridHz_)) + 2;
    grid_.resize(n);
    GridPoint g{heading0, 0.0, 0.0, 0.0};
    const double h = 1.0 / gridHz_;
    for (std::size_t i = 0; i < n; ++i) {
        const double t = double(i) * h;
        g.heading = heading0 + shiftAngle(bodyTurns_, 0, t);
        grid_[i] = g;
        const double psi = degToRad(g.heading);
        g.x += -std::sin(psi) * speed_ * h;  // forward is -Z turned by the heading about +Y
        g.z += -std::cos(psi) * speed_ * h;
        g.torsoYaw += (shiftAngle(headShifts_, 0, t) - g.torsoYaw) * (h / kTorsoLag);
    }
}

ActivityModel::GridPoint ActivityModel::grid(double t) const {
    const double u = std::clamp(t * gridHz_, 0.0, double(grid_.size() - 1));
    const auto i = std::min(static_cast<std::size_t>(u), grid_.size() - 2);
    const double f = u - double(i);
    const GridPoint &a = grid_[i], &b = grid_[i + 1];
    return GridPoint{a.heading + f * (b.heading - a.heading), a.x + f * (b.x - a.x), a.z + f * (b.z - a.z),
                     a.torsoYaw + f * (b.torsoYaw - a.torsoYaw)};
}

double ActivityModel::shiftAngle(const std::vector<Shift>& shifts, int axis, double t) const {
    double sum = 0.0;
    for (const auto& s : shifts) {
        if (t <= s.start) break;
        sum += s.d[axis] * minimumJerk((t - s.start) / s.duration);
    }
    return sum;
}

double ActivityModel::gaitPhase(double t) const {
    // Integral of 2 pi f(t) with f = stepHz (1 + depth sin(2 pi fm t)).
    const double fm = stepModHz_;
    return gaitPhase0_ + kTwoPi * stepHz_ * (t + stepModDepth_ * (1.0 - std::cos(kTwoPi * fm * t)) / (kTwoPi * fm));
}

PoseSample ActivityModel::at(double t) const {
    const GridPoint g = grid(t);
    double yaw = 0.0, pitch = 0.0, roll = 0.0;  // degrees
    Eigen::Vector3d p;
    if (params_.activity == Activity::Walk) {
        const double phi = gaitPhase(t);
        yaw = g.heading + 1.0 * (std::sin(0.5 * phi) + std::sin(phi + 0.7) / 3.0);
        for (const auto& w : yawSweep_) yaw += wave(w.amplitude, w.hz, w.phase, t);
        pitch = -8.0 + 1.5 * (std::sin(phi) + std::sin(2.0 * phi + 1.1) / 3.0);
        for (const auto& w : pitchSweep_) pitch += wave(w.amplitude, w.hz, w.phase, t);
        roll = 1.5 * (std::sin(0.5 * phi + 0.4) + std::sin(phi + 2.0) / 3.0);
        const double psi = degToRad(g.heading);
        const Eigen::Vector3d right(std::cos(psi), 0.0, -std::sin(psi));
        const double bob = 0.02 * (std::cos(phi) + std::cos(2.0 * phi + 0.5) / 3.0);
        const double side = 0.02 * (std::sin(0.5 * phi) + std::sin(phi + 0.3) / 3.0);
        p = Eigen::Vector3d(g.x, 1.55 + bob, g.z) + side * right;
    } else {
        yaw = shiftAngle(headShifts_, 0, t);
        pitch = shiftAngle(headShifts_, 1, t);
        roll = shiftAngle(headShifts_, 2, t);
        const Eigen::Vector3d sway(wave(swayPos_[0].amplitude, swayPos_[0].hz, swayPos_[0].phase, t), 0.0,
                                   wave(swayPos_[2].amplitude, swayPos_[2].hz, swayPos_[2].phase, t));
        // The neck pivot 5 cm in front of the torso's vertical axis, turning with the torso.
        p = Eigen::Vector3d(0.0, 1.5, 0.0) + sway +
            Eigen::AngleAxisd(degToRad(g.torsoYaw), Eigen::Vector3d::UnitY()) * Eigen::Vector3d(0.0, 0.0, -0.05);
    }
    const Eigen::Quaterniond q = Eigen::AngleAxisd(degToRad(yaw), Eigen::Vector3d::UnitY()) *
                                 Eigen::AngleAxisd(degToRad(pitch), Eigen::Vector3d::UnitX()) *
                                 Eigen::AngleAxisd(degToRad(roll), Eigen::Vector3d::UnitZ());
    if (params_.activity == Activity::Scan) p += q * Eigen::Vector3d(0.0, 0.10, -0.09);  // eyes from the pivot
    return PoseSample{t, p, q.normalized()};
}

std::string ActivityModel::describe() const {
    const auto& p = params_;
    char buf[512];
    const std::size_t events = p.activity == Activity::Scan ? headShifts_.size() : bodyTurns_.size();
    std::snprintf(buf, sizeof buf,
                  "activity head motion (%s): seed %llu, %.3g s, %zu %s, sensor %g Hz, noise %g deg / %g mm, "
                  "jitter %g ms, burst dropouts %g",
                  std::string(activityName(p.activity)).c_str(), static_cast<unsigned long long>(p.seed),
                  p.duration, events, p.activity == Activity::Scan ? "gaze shifts" : "body turns", p.sampleHz,
                  p.noiseDeg, p.noiseMm, p.jitterMs, p.burstProbability);
    return buf;
}

SyntheticTraces generateActivityMotion(const ActivityParams& params) {
    const ActivityModel model(params);
    SyntheticTraces out;
    out.truth = sampleModel(model, params.duration, params.truthHz);
    SeededRng rng(params.seed ^ 0xd1b54a32d192ed03ull);  // the sensor's stream, apart from the motion's
    const double noise = degToRad(params.noiseDeg);
    if (params.sampleHz > 0.0) {
        const auto n = static_cast<long long>(std::floor(params.duration * params.sampleHz));
        double previous = -1e300;
        int lost = 0;  // samples still to drop in the current burst
        for (long long i = 0; i <= n; ++i) {
            const double jitter = params.jitterMs * 1e-3 * rng.normal();
            const bool burst = rng.uniform() < params.burstProbability;
            const int burstLength = 2 + int(rng.uniform() * 7.0);  // 2..8
            const Eigen::Vector3d rotNoise(rng.normal(), rng.normal(), rng.normal());
            const Eigen::Vector3d posNoise(rng.normal(), rng.normal(), rng.normal());
            if (lost == 0 && burst && i > 0) lost = burstLength;
            if (lost > 0) {
                --lost;
                continue;
            }
            const double t = std::clamp(double(i) / params.sampleHz + jitter, 0.0, params.duration);
            if (t < previous) continue;  // a tracker stamps monotonically
            previous = t;
            PoseSample s = model.at(t);
            s.p += params.noiseMm * 1e-3 * posNoise;
            s.q = safeNormalized(quatExp(noise * rotNoise) * s.q);
            out.measured.push_back(s);
        }
    }
    return out;
}

}  // namespace strata::tracking
