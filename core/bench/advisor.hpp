#pragma once
// `strata advise`: measures the techniques on this device, each at its defaults and at the other
// values of the settings that trade speed for accuracy (capacities, sample counts, bucket counts,
// supersampling, precision, the overflow tail), and recommends one. The cost is the frame's GPU
// time (opaque pass included: what a frame budget is spent on), the loss the RMSE against the
// exact reference (linear RGB), both from `strata bench` (bench/bench.hpp).
//
// The rule, stated once (recommend()):
//  - with a budget: the most accurate configuration whose frame fits it; of those within 1 % of
//    the least error, the fastest;
//  - with an error bound: the fastest configuration within it;
//  - with both: the most accurate of those within both, else as with the budget alone;
//  - with neither: the fastest within kDefaultMaxRmse (1/255, what an 8-bit display shows).
// Where nothing qualifies it says so and falls back: the fastest overall under a budget, the
// most accurate overall under an error bound.
#include <nlohmann/json.hpp>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace strata {

// One configuration to measure: a technique and the `name=value` assignments that differ from
// its defaults (empty: the defaults).
struct AdvisorCandidate {
    std::string id;
    std::vector<std::string> assignments;
    std::string label() const;  // "ll capacity=16", "abuffer"
};

// Every technique of `ids` (empty: the whole registry but `floor`, which draws nothing
// transparent; an id given twice counts once) at its defaults, then, with `trades`, each at the
// other values of its trading settings; a reference (abuffer, abuffer-volume) at its defaults
// only, since a bench measures it against itself. Throws std::invalid_argument for an unknown id.
std::vector<AdvisorCandidate> advisorCandidates(const std::vector<std::string>& ids, bool trades);

class GpuScene;
struct BenchOptions;

struct AdvisorPoint;
// Measures the candidates with `strata bench`'s machinery (bench/bench.hpp): `base` gives the
// size, frames and camera path; modes and settings are set per candidate. Every candidate at its
// defaults runs in one bench, each other configuration in its own. With `tradeLimitMs` > 0 the
// trades of a technique whose defaults took longer than that are not measured (`strata advise`
// passes 4 x the budget: no trade here saves that much). A run stopped by a signal returns the
// points measured so far. Needs a current GL context.
std::vector<AdvisorPoint> measureCandidates(const GpuScene& scene, const std::vector<AdvisorCandidate>& candidates,
                                            const BenchOptions& base,
                                            const std::function<void(const std::string&)>& progress,
                                            double tradeLimitMs = 0.0);

struct AdvisorPoint {
    AdvisorCandidate candidate;
    double frameMs = 0.0;      // median GPU ms of the whole frame
    double techniqueMs = 0.0;  // median GPU ms of the technique's passes
    double rmse = 0.0, psnr = 100.0, maxAbsError = 0.0;
    bool overflowed = false;
    std::uint64_t bytes = 0;
    std::string reference;     // what its error is measured against (benchReferenceOf)
    bool pareto = false;       // no other point is as fast and as accurate, and better in one
};

struct AdvisorCriteria {
    std::optional<double> budgetMs;
    std::optional<double> maxRmse;
};

constexpr double kDefaultMaxRmse = 1.0 / 255.0;

struct AdvisorPick {
    int index = -1;      // into the points; -1 only for an empty list
    std::string reason;  // one line: which rule chose it, or why it fell back
};

// Sets AdvisorPoint::pareto.
void markPareto(std::vector<AdvisorPoint>& points);

AdvisorPick recommend(const std::vector<AdvisorPoint>& points, const AdvisorCriteria& criteria);

// The Pareto front first (fastest to slowest), then the rest, one row each; the pick marked.
std::string advisorTable(const std::vector<AdvisorPoint>& points, const AdvisorPick& pick);

// Frame time (x, logarithmic) against RMSE (y, logarithmic) in characters: '*' the Pareto
// front, '.' the rest, '@' the pick; the axes' ranges underneath.
std::string advisorPlot(const std::vector<AdvisorPoint>& points, const AdvisorPick& pick, int width = 64,
                        int height = 16);

// What `bench --modes auto` and `view --mode auto` run: every technique with its trades at
// `base`'s size, two frames and one warm-up each, under the default rule. Prints one line naming
// the pick through `progress`. Throws Interrupted (io/interrupt.hpp) when a signal stopped it
// before anything was measured.
AdvisorCandidate autoPick(const GpuScene& scene, BenchOptions base,
                          const std::function<void(const std::string&)>& progress);

nlohmann::json advisorToJson(const std::vector<AdvisorPoint>& points, const AdvisorPick& pick,
                             const AdvisorCriteria& criteria);

}  // namespace strata
