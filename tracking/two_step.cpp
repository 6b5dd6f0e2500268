#include "tracking/two_step.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace strata::tracking {

std::vector<FramePoses> simulateTwoStep(const Predictor& prototype, const Trace& measured, const Trace& truth,
                                        const TwoStepConfig& config) {
    std::vector<FramePoses> frames;
    if (measured.empty() || truth.empty() || !(config.displayHz > 0.0)) return frames;
    auto atStart = prototype.clone();
    auto atReread = prototype.clone();
    atStart->reset();
    atReread->reset();
    const double latency = std::max(0.0, config.latency);
    const double reread = std::clamp(config.reread, 0.0, latency);
    const double first = std::max(measured.front().t, truth.front().t) + std::max(config.warmup, latency);
    const double last = std::min(measured.back().t, truth.back().t);
    const double period = 1.0 / config.displayHz;
    std::size_t ia = 0, ib = 0;
    for (long long n = 0;; ++n) {
        const double td = first + double(n) * period;  // no accumulated round-off over long traces
        if (td > last) break;
        while (ia < measured.size() && measured[ia].t <= td - latency) atStart->update(measured[ia++]);
        while (ib < measured.size() && measured[ib].t <= td - reread) atReread->update(measured[ib++]);
        frames.push_back(FramePoses{td, atStart->predict(td), atReread->predict(td), sampleAt(truth, td)});
    }
    return frames;
}

ErrorStats summarize(const std::vector<FramePoses>& frames, Deflect deflect, const Intrinsics& k) {
    ErrorStats s;
    s.frames = frames.size();
    if (frames.empty()) return s;
    std::vector<double> angles;
    angles.reserve(frames.size());
    double sumDeg = 0.0, sumMm = 0.0, sumApprox = 0.0;
    for (const auto& f : frames) {
        const ViewingError e = viewingError(deflect, k, f.rendered, f.reread, f.truth);
        angles.push_back(e.angleDeg);
        sumDeg += e.angleDeg;
        sumMm += e.positionMm;
        sumApprox += e.approximationDeg;
    }
    const double n = double(frames.size());
    s.meanDeg = sumDeg / n;
    s.meanMm = sumMm / n;
    s.meanApproximationDeg = sumApprox / n;
    std::sort(angles.begin(), angles.end());
    s.maxDeg = angles.back();
    // Nearest-rank percentile: the smallest value with at least 95 % of frames at or below it.
    const auto rank = static_cast<std::size_t>(std::ceil(0.95 * n));
    s.p95Deg = angles[std::clamp<std::size_t>(rank, 1, angles.size()) - 1];
    return s;
}

double measureUpdateNs(const Predictor& prototype, const Trace& measured, double minSeconds) {
    if (measured.empty()) return 0.0;
    auto p = prototype.clone();
    volatile double sink = 0.0;  // keeps the work observable so it is not optimised away
    using clock = std::chrono::steady_clock;
    const auto begin = clock::now();
    double best = 1e300;
    int passes = 0;
    do {
        const auto start = clock::now();
        p->reset();
        for (const auto& s : measured) p->update(s);
        sink = sink + p->predict(measured.back().t).q.w();
        const double pass = std::chrono::duration<double>(clock::now() - start).count();
        best = std::min(best, pass);
        ++passes;
    } while (passes < 3 || std::chrono::duration<double>(clock::now() - begin).count() < minSeconds);
    return best * 1e9 / double(measured.size());
}

}  // namespace strata::tracking
