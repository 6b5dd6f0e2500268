#include "bench/advisor.hpp"

#include "bench/bench.hpp"
#include "io/interrupt.hpp"
#include "oit/technique.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace strata {
namespace {

// The other values worth measuring of a setting that trades speed for accuracy; none for a
// setting that does not (seeds, pass bounds, memory caps) or whose trade is measured elsewhere.
std::vector<double> tradeValues(const SettingDescription& d, bool hasTail) {
    std::vector<double> values;
    if (d.name == "capacity") values = {4, 16, 32};
    else if (d.name == "samples") values = {4, 16, 32};
    else if (d.name == "buckets") values = {4, 16};
    else if (d.name == "supersampling") values = {2, 8};
    // Precision: the other of 16 and 32. Where it only sizes the overflow tail's targets
    // (kbuffer, fab, ll with tail off), it changes nothing at the defaults.
    else if (d.name == "precision" && !hasTail) values = d.allowed;
    // The overflow tail (blend what does not fit instead of dropping it); the compute resolve and
    // dual's atomic range (the same image, another cost: which is faster depends on the device).
    else if ((d.name == "tail" || d.name == "compute_resolve" || d.name == "atomic_range") && d.defaultValue == 0.0)
        values = {1};
    std::vector<double> out;
    for (double v : values)
        if (v != d.defaultValue && v >= d.min && v <= d.max) out.push_back(v);
    return out;
}

// The most accurate of `indices`: the least RMSE, and among the points within 1 % of it the
// fastest (measured from the least, so that a chain of near-equal points cannot drift).
int mostAccurate(const std::vector<AdvisorPoint>& points, const std::vector<int>& indices) {
    if (indices.empty()) return -1;
    double least = points[std::size_t(indices.front())].rmse;
    for (int i : indices) least = std::min(least, points[std::size_t(i)].rmse);
    int best = -1;
    for (int i : indices) {
        const AdvisorPoint& p = points[std::size_t(i)];
        if (p.rmse > least * 1.01 + 1e-12) continue;
        if (best < 0 || p.frameMs < points[std::size_t(best)].frameMs) best = i;
    }
    return best;
}

int fastest(const std::vector<AdvisorPoint>& points, const std::vector<int>& indices) {
    int best = -1;
    for (int i : indices)
        if (best < 0 || points[std::size_t(i)].frameMs < points[std::size_t(best)].frameMs) best = i;
    return best;
}

std::string fixed(const char* format, double value) {
    char text[64];
    std::snprintf(text, sizeof text, format, value);
    return text;
}

}  // namespace

std::string AdvisorCandidate::label() const {
    std::string text = id;
    for (const std::string& a : assignments) text += " " + a;
    return text;
}

std::vector<AdvisorCandidate> advisorCandidates(const std::vector<std::string>& ids, bool trades) {
    std::vector<const TechniqueEntry*> entries;
    if (ids.empty()) {
        for (const TechniqueEntry& e : techniqueRegistry())
            if (e.info.id != "floor") entries.push_back(&e);
    } else {
        for (const std::string& id : ids) {
            const TechniqueEntry* e = findTechnique(id);
            if (!e) throw std::invalid_argument("unknown technique '" + id + "' (see `strata modes`)");
            entries.push_back(e);
        }
    }
    std::vector<const TechniqueEntry*> unique;
    for (const TechniqueEntry* e : entries)
        if (std::find(unique.begin(), unique.end(), e) == unique.end()) unique.push_back(e);
    entries = unique;
    std::vector<AdvisorCandidate> out;
    for (const TechniqueEntry* e : entries) out.push_back({e->info.id, {}});
    if (!trades) return out;
    for (const TechniqueEntry* e : entries) {
        // A reference's own trades would be measured against themselves (the bench configures the
        // reference it runs with them): only their defaults are measured.
        if (benchReferenceOf(e->info.id) == e->info.id) continue;
        const bool hasTail = std::any_of(e->settings.begin(), e->settings.end(),
                                         [](const SettingDescription& d) { return d.name == "tail"; });
        for (const SettingDescription& d : e->settings)
            for (double v : tradeValues(d, hasTail)) out.push_back({e->info.id, {d.name + "=" + formatSettingValue(d, v)}});
    }
    return out;
}

namespace {

AdvisorPoint pointOf(const AdvisorCandidate& candidate, const BenchMode& m) {
    AdvisorPoint p;
    p.candidate = candidate;
    p.frameMs = m.frameMsMedian;
    p.techniqueMs = m.msMedian;
    p.rmse = m.rmse;
    p.psnr = m.psnr;
    p.maxAbsError = m.maxAbsError;
    p.overflowed = m.overflowed;
    p.bytes = m.bytes;
    p.reference = m.reference;
    return p;
}

}  // namespace

std::vector<AdvisorPoint> measureCandidates(const GpuScene& scene, const std::vector<AdvisorCandidate>& candidates,
                                            const BenchOptions& base,
                                            const std::function<void(const std::string&)>& progress,
                                            double tradeLimitMs) {
    std::vector<AdvisorPoint> points;
    auto say = [&](const std::string& line) {
        if (progress) progress(line);
    };
    auto report = [&](const AdvisorPoint& p) {
        say("advise: [" + std::to_string(points.size()) + "/" + std::to_string(candidates.size()) + "] " +
            p.candidate.label() + ": frame " + fixed("%.3f", p.frameMs) + " ms, RMSE " + fixed("%.2e", p.rmse));
    };
    std::vector<std::string> defaults;
    for (const AdvisorCandidate& c : candidates)
        if (c.assignments.empty()) defaults.push_back(c.id);
    if (!defaults.empty()) {
        BenchOptions o = base;
        o.modes = defaults;
        o.settings = resolveSettings(benchModeIds(defaults), {});
        o.progress = progress;
        const BenchReport r = runBench(scene, o);
        for (const AdvisorCandidate& c : candidates) {
            if (!c.assignments.empty()) continue;
            for (const BenchMode& m : r.modes)
                if (m.id == c.id) {
                    points.push_back(pointOf(c, m));
                    report(points.back());
                }
        }
        if (r.interrupted) return points;
    }
    std::size_t skipped = 0;
    for (const AdvisorCandidate& c : candidates) {
        if (c.assignments.empty()) continue;
        if (tradeLimitMs > 0.0) {
            const auto defaults = std::find_if(points.begin(), points.end(), [&](const AdvisorPoint& p) {
                return p.candidate.id == c.id && p.candidate.assignments.empty();
            });
            if (defaults != points.end() && defaults->frameMs > tradeLimitMs) {
                ++skipped;
                continue;
            }
        }
        BenchOptions o = base;
        o.modes = {c.id};
        std::vector<SettingAssignment> assignments;
        for (const std::string& a : c.assignments) assignments.push_back({c.id + "." + a, "the advisor"});
        o.settings = resolveSettings(benchModeIds(o.modes), assignments);
        o.progress = nullptr;
        const BenchReport r = runBench(scene, o);
        for (const BenchMode& m : r.modes)
            if (m.id == c.id) {
                points.push_back(pointOf(c, m));
                report(points.back());
            }
        if (r.interrupted) break;
    }
    if (skipped)
        say("advise: " + std::to_string(skipped) + " trades not measured: their techniques' defaults took over " +
            fixed("%.3g", tradeLimitMs) + " ms");
    return points;
}

AdvisorCandidate autoPick(const GpuScene& scene, BenchOptions base,
                          const std::function<void(const std::string&)>& progress) {
    base.zoom = 1;  // as `strata advise` measures: zoom 1, every object as geometry
    base.budget.reset();
    base.lod = nullptr;
    base.frames = 2;
    base.warmupFrames = 1;
    std::vector<AdvisorPoint> points = measureCandidates(scene, advisorCandidates({}, true), base, progress);
    if (points.empty()) throw Interrupted(interruptSignal());
    markPareto(points);
    const AdvisorPick pick = recommend(points, {});
    const AdvisorPoint& p = points[std::size_t(pick.index)];
    if (progress)
        progress("auto: " + p.candidate.label() + " (" + pick.reason + ", of " + std::to_string(points.size()) +
                 " configurations): frame " + fixed("%.3f", p.frameMs) + " ms, RMSE " + fixed("%.2e", p.rmse));
    return p.candidate;
}

void markPareto(std::vector<AdvisorPoint>& points) {
    for (AdvisorPoint& p : points) {
        p.pareto = std::none_of(points.begin(), points.end(), [&](const AdvisorPoint& q) {
            return &q != &p && q.frameMs <= p.frameMs && q.rmse <= p.rmse && (q.frameMs < p.frameMs || q.rmse < p.rmse);
        });
    }
}

AdvisorPick recommend(const std::vector<AdvisorPoint>& points, const AdvisorCriteria& criteria) {
    AdvisorPick pick;
    if (points.empty()) return pick;
    auto where = [&](auto&& qualifies) {
        std::vector<int> out;
        for (int i = 0; i < int(points.size()); ++i)
            if (qualifies(points[std::size_t(i)])) out.push_back(i);
        return out;
    };
    const std::vector<int> all = where([](const AdvisorPoint&) { return true; });
    auto fits = [&](const AdvisorPoint& p) { return !criteria.budgetMs || p.frameMs <= *criteria.budgetMs; };
    const double maxRmse = criteria.maxRmse.value_or(kDefaultMaxRmse);
    auto accurate = [&](const AdvisorPoint& p) { return p.rmse <= maxRmse; };
    const std::string bound = "RMSE " + fixed("%.2g", maxRmse);
    if (criteria.budgetMs) {
        const std::string budget = fixed("%.3g", *criteria.budgetMs) + " ms";
        if (criteria.maxRmse) {
            pick.index = mostAccurate(points, where([&](const AdvisorPoint& p) { return fits(p) && accurate(p); }));
            if (pick.index >= 0) {
                pick.reason = "the most accurate within " + budget + " and " + bound;
                return pick;
            }
        }
        pick.index = mostAccurate(points, where(fits));
        if (pick.index >= 0) {
            pick.reason = std::string(criteria.maxRmse ? "nothing met both bounds; " : "") + "the most accurate within " + budget;
            return pick;
        }
        pick.index = fastest(points, all);
        pick.reason = "nothing fits " + budget + "; the fastest";
        return pick;
    }
    pick.index = fastest(points, where(accurate));
    if (pick.index >= 0) {
        pick.reason = "the fastest within " + bound + (criteria.maxRmse ? "" : " (the default bound: 1/255)");
        return pick;
    }
    pick.index = mostAccurate(points, all);
    pick.reason = "nothing is within " + bound + "; the most accurate";
    return pick;
}

std::string advisorTable(const std::vector<AdvisorPoint>& points, const AdvisorPick& pick) {
    std::vector<int> order(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) order[i] = int(i);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
        const AdvisorPoint &p = points[std::size_t(a)], &q = points[std::size_t(b)];
        if (p.pareto != q.pareto) return p.pareto;
        return p.frameMs < q.frameMs;
    });
    std::size_t width = 13;
    for (const AdvisorPoint& p : points) width = std::max(width, p.candidate.label().size());
    std::string out;
    char line[256];
    std::snprintf(line, sizeof line, "  %-*s %10s %10s %10s %8s %10s %-14s %s\n", int(width), "configuration",
                  "frame ms", "tech ms", "RMSE", "PSNR", "memory", "against", "");
    out += line;
    for (int i : order) {
        const AdvisorPoint& p = points[std::size_t(i)];
        std::snprintf(line, sizeof line, "%c %-*s %10.3f %10.3f %10.2e %8.1f %10s %-14s %s%s\n", i == pick.index ? '>' : ' ',
                      int(width), p.candidate.label().c_str(), p.frameMs, p.techniqueMs, p.rmse, p.psnr,
                      humanBytes(p.bytes).c_str(), p.reference.c_str(), p.pareto ? "front" : "",
                      p.overflowed ? " overflowed" : "");
        out += line;
    }
    return out;
}

std::string advisorPlot(const std::vector<AdvisorPoint>& points, const AdvisorPick& pick, int width, int height) {
    if (points.empty() || width < 8 || height < 4) return "";
    // Logarithmic axes; an exact configuration's RMSE (round-off, ~1e-6) is floored at 1e-6.
    constexpr double kFloorRmse = 1e-6;
    double x0 = std::numeric_limits<double>::max(), x1 = 0.0, y0 = x0, y1 = 0.0;
    for (const AdvisorPoint& p : points) {
        const double x = std::max(p.frameMs, 1e-6), y = std::max(p.rmse, kFloorRmse);
        x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
    auto scale = [](double v, double lo, double hi, int cells) {
        if (hi <= lo * (1.0 + 1e-9)) return 0;
        return std::clamp(int(std::lround((std::log(v) - std::log(lo)) / (std::log(hi) - std::log(lo)) * (cells - 1))), 0,
                          cells - 1);
    };
    std::vector<std::string> grid(std::size_t(height), std::string(std::size_t(width), ' '));
    auto put = [&](int i, char mark) {
        const AdvisorPoint& p = points[std::size_t(i)];
        const int col = scale(std::max(p.frameMs, 1e-6), x0, x1, width);
        const int row = height - 1 - scale(std::max(p.rmse, kFloorRmse), y0, y1, height);
        char& cell = grid[std::size_t(row)][std::size_t(col)];
        if (cell != '@' && !(cell == '*' && mark == '.')) cell = mark;
    };
    for (int i = 0; i < int(points.size()); ++i) put(i, points[std::size_t(i)].pareto ? '*' : '.');
    if (pick.index >= 0) put(pick.index, '@');
    std::string out = "RMSE (log) " + fixed("%.2g", y1) + " at the top, " + fixed("%.2g", y0) +
                      " at the bottom; '*' Pareto front, '.' dominated, '@' recommended\n";
    for (const std::string& row : grid) out += " |" + row + "\n";
    out += " +" + std::string(std::size_t(width), '-') + "\n";
    out += "  frame ms (log): " + fixed("%.3g", x0) + " at the left, " + fixed("%.3g", x1) + " at the right\n";
    return out;
}

nlohmann::json advisorToJson(const std::vector<AdvisorPoint>& points, const AdvisorPick& pick,
                             const AdvisorCriteria& criteria) {
    nlohmann::json j;
    // The error bound that applied: none under a budget alone.
    const bool boundApplies = criteria.maxRmse || !criteria.budgetMs;
    j["criteria"] = {{"budget_ms", criteria.budgetMs ? nlohmann::json(*criteria.budgetMs) : nlohmann::json()},
                     {"max_rmse", boundApplies ? nlohmann::json(criteria.maxRmse.value_or(kDefaultMaxRmse)) : nlohmann::json()},
                     {"max_rmse_given", criteria.maxRmse.has_value()}};
    j["configurations"] = nlohmann::json::array();
    for (const AdvisorPoint& p : points)
        j["configurations"].push_back({{"id", p.candidate.id},
                                       {"settings", p.candidate.assignments},
                                       {"label", p.candidate.label()},
                                       {"frame_ms", p.frameMs},
                                       {"technique_ms", p.techniqueMs},
                                       {"rmse", p.rmse},
                                       {"reference", p.reference},
                                       {"psnr", p.psnr},
                                       {"max_abs_error", p.maxAbsError},
                                       {"bytes", p.bytes},
                                       {"overflowed", p.overflowed},
                                       {"pareto", p.pareto}});
    if (pick.index >= 0) {
        const AdvisorPoint& p = points[std::size_t(pick.index)];
        j["recommended"] = {{"id", p.candidate.id}, {"settings", p.candidate.assignments}, {"label", p.candidate.label()},
                            {"frame_ms", p.frameMs}, {"rmse", p.rmse}, {"reason", pick.reason}};
    } else {
        j["recommended"] = nullptr;
    }
    return j;
}

}  // namespace strata
