#pragma once
// A second synthetic head-motion generator, built differently from synthetic.hpp's seated
// viewer so that no single model is both the set the predictors are tuned on and the set they
// are tested on. Two activities:
//
// walk: a viewer walking about a room while looking around.
//  - The body follows a heading that changes by slow min-jerk re-orientations (30-120 deg over
//    1.5-3.5 s, then 1-4 s straight), walking at 1.1-1.5 m/s; the path is integrated from the
//    heading and the speed (no closed form), on a 1 kHz grid.
//  - Gait (Pozzo, Berthoz, Lefort 1990, "Head stabilization during various locomotor tasks in
//    humans"; Hirasaki et al. 1999): the step frequency is 1.7-2.1 Hz, slowly modulated; the
//    head bobs vertically at the step frequency (+-2 cm) and sways sideways at the stride
//    frequency (half the step frequency, +-2 cm); the head pitches at the step frequency
//    (+-1.5 deg, partly compensating the bob) and rolls and yaws at the stride frequency
//    (+-1.5 deg, +-1 deg). Each oscillation carries its second harmonic at a third of its
//    amplitude (heel strikes are not sinusoidal).
//  - Looking around relative to the body: slow yaw sweeps (three sinusoids at 0.05-0.35 Hz,
//    8-25 deg each) and pitch sweeps (two at 0.05-0.25 Hz, 4-10 deg) about a slight downward gaze.
//
// scan: a standing viewer searching the surroundings with fast, saccade-like head turns.
//  - Gaze shifts of 20-120 deg, mostly horizontal (pitch a quarter of the span), about a
//    direction that also rolls the head by a tenth of the yaw change (head turns are not pure
//    yaw); peak speed 150-450 deg/s rising with amplitude (faster than synthetic.hpp's
//    100-300); the minimum-jerk profile (Flash & Hogan 1985) of each shift.
//  - Short fixations (0.08-0.5 s), and in a third of the shifts the next one starts before the
//    last has ended (at 55-90 % of its duration), so velocity profiles overlap; two in five
//    large shifts (> 40 deg) end with a small corrective turn (2-6 deg) 80-200 ms later.
//  - The torso follows the head's yaw with a first-order lag (time constant 0.6 s), carrying the
//    neck pivot; the eyes sit 10 cm above and 9 cm in front of the pivot. Postural sway of
//    +-1.5 cm at 0.1-0.3 Hz.
//
// Sensor (both activities; a camera-tracked HMD rather than synthetic.hpp's IMU-like one):
// 90 Hz with timestamp jitter N(0, 0.5 ms), orientation noise 0.03 deg and position noise
// 0.3 mm per axis (white, world frame), and burst dropouts: with probability 0.004 per sample
// a run of 2-8 consecutive samples is lost (occlusion), instead of single missing samples.
//
// Truth is sampled at truthHz without noise. Randomness as in synthetic.hpp: std::mt19937_64
// with hand-written uniform and Box-Muller draws, so a seed gives the same traces anywhere.
#include "tracking/synthetic.hpp"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace strata::tracking {

enum class Activity { Walk, Scan };

std::string_view activityName(Activity activity);
// "walk" or "scan"; throws std::invalid_argument naming the known ones otherwise.
Activity parseActivity(std::string_view name);

struct ActivityParams {
    Activity activity = Activity::Walk;
    double duration = 10.0;  // s
    std::uint64_t seed = 1;
    double sampleHz = 90.0, truthHz = 1000.0;
    double noiseDeg = 0.03, noiseMm = 0.3, jitterMs = 0.5;
    double burstProbability = 0.004;  // per sample, start of a 2-8 sample dropout
};

class ActivityModel {
public:
    explicit ActivityModel(const ActivityParams& params);
    PoseSample at(double t) const;
    std::string describe() const;

private:
    struct Wave {
        double amplitude, hz, phase;
    };
    struct Shift {  // one min-jerk change of (yaw, pitch, roll) in degrees
        double start, duration, d[3];
    };
    // Slowly varying state integrated on a grid (walk: body heading and position; scan: torso
    // yaw), linearly interpolated between grid points.
    struct GridPoint {
        double heading, x, z, torsoYaw;
    };
    GridPoint grid(double t) const;
    double shiftAngle(const std::vector<Shift>& shifts, int axis, double t) const;
    double gaitPhase(double t) const;

    ActivityParams params_;
    std::vector<GridPoint> grid_;
    double gridHz_ = 1000.0;
    std::vector<Shift> headShifts_, bodyTurns_;
    Wave yawSweep_[3], pitchSweep_[2], swayPos_[3];
    double stepHz_ = 1.9, stepModHz_ = 0.1, stepModDepth_ = 0.05, gaitPhase0_ = 0.0, speed_ = 1.3;
};

SyntheticTraces generateActivityMotion(const ActivityParams& params);

}  // namespace strata::tracking
