#pragma once
// Two-step prediction over a recorded trace, and the statistics `strata track` reports.
//
// For each displayed frame with display time td (frames at displayHz):
//  1. frame start at td - latency: the predictor has seen every measured sample with
//     t <= td - latency and predicts the pose at td; that pose is rendered;
//  2. re-read at td - reread (clamped to the frame start): the predictor has seen every sample
//     with t <= td - reread and predicts td again; deflection moves the image towards it;
//  3. the truth at td is interpolated from the truth trace.
// The two steps run on two copies of the same causal predictor fed up to different cut-offs,
// which is what a single predictor queried at those two wall-clock times would hold. The age
// of the latest sample (up to one tracker period) is part of the real prediction horizon and
// therefore part of the measured error.
#include "tracking/predictor.hpp"
#include "tracking/viewing_error.hpp"

#include <cstddef>
#include <vector>

namespace strata::tracking {

struct TwoStepConfig {
    double latency = 0.050;   // s, frame start to display
    double reread = 0.005;    // s, second tracker read before display
    double displayHz = 90.0;  // frames scored per second
    double warmup = 0.5;      // s after the first sample before frames are scored
};

struct FramePoses {
    double displayTime = 0.0;
    PoseSample rendered, reread, truth;
};

std::vector<FramePoses> simulateTwoStep(const Predictor& prototype, const Trace& measured, const Trace& truth,
                                        const TwoStepConfig& config);

struct ErrorStats {
    std::size_t frames = 0;
    double meanDeg = 0.0, p95Deg = 0.0, maxDeg = 0.0;
    double meanMm = 0.0;
    double meanApproximationDeg = 0.0;  // shift only
};

ErrorStats summarize(const std::vector<FramePoses>& frames, Deflect deflect, const Intrinsics& k);

// Wall time of one update() in nanoseconds on steady_clock: the measured trace is fed in passes
// (reset between them) for at least minSeconds and three passes; the fastest pass's mean per
// update is reported, because on a shared machine slower passes measure preemption, not code.
double measureUpdateNs(const Predictor& prototype, const Trace& measured, double minSeconds = 0.05);

}  // namespace strata::tracking
