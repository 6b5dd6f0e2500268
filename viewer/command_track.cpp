// `strata track`: replays a head-pose trace through the predictors with two-step prediction and
// image deflection, and reports the viewing error each combination leaves and what an update
// costs. No GL: everything here runs on the CPU (tracking/ library).
#include "io/atomic_file.hpp"
#include "io/interrupt.hpp"
#include "io/parse_integers.hpp"
#include "io/printable.hpp"
#include "tracking/activity_motion.hpp"
#include "tracking/kalman.hpp"
#include "tracking/predictor.hpp"
#include "tracking/synthetic.hpp"
#include "tracking/trace_io.hpp"
#include "tracking/two_step.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace strata {
namespace {

using namespace strata::tracking;

struct TrackOptions {
    std::string trace, truth, json, sweepCsv, writeTraces, size = "1920x1080";
    std::string predictors = "all", deflects = "none,shift,homography", motion = "seated";
    double latencyMs = 50.0, rereadMs = 5.0, displayHz = 90.0, fovDeg = 90.0, synthetic = 0.0;
    std::uint64_t seed = 1;
};

std::vector<std::string> splitList(const std::string& text) {
    std::vector<std::string> out;
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, ','))
        if (!item.empty()) out.push_back(item);
    return out;
}

std::vector<std::unique_ptr<Predictor>> selectPredictors(const std::string& list) {
    std::vector<std::unique_ptr<Predictor>> out;
    const auto names = list == "all" ? predictorNames() : splitList(list);
    for (const auto& n : names) {
        try {
            out.push_back(makePredictor(n));
        } catch (const std::invalid_argument& e) {
            throw std::runtime_error(std::string("--predictor: ") + e.what());
        }
    }
    if (out.empty()) throw std::runtime_error("--predictor: empty list");
    return out;
}

std::vector<Deflect> selectDeflects(const std::string& list) {
    std::vector<Deflect> out;
    const auto names = list == "all" ? std::vector<std::string>{"none", "shift", "homography"} : splitList(list);
    for (const auto& n : names) {
        try {
            out.push_back(parseDeflect(n));
        } catch (const std::invalid_argument& e) {
            throw std::runtime_error(std::string("--deflect: ") + e.what());
        }
    }
    if (out.empty()) throw std::runtime_error("--deflect: empty list");
    return out;
}

Intrinsics parseIntrinsics(const std::string& size, double fovDeg) {
    const auto wh = parseIntPair(size, "xX");
    if (!wh || wh->first < 1 || wh->second < 1)
        throw std::runtime_error("--size `" + printable(size, 40) + "`: expected WIDTHxHEIGHT, e.g. 1920x1080");
    if (!(fovDeg > 0.0 && fovDeg < 179.0)) throw std::runtime_error("--fov-deg: must be in (0, 179)");
    return Intrinsics::fromFov(wh->first, wh->second, fovDeg);
}

// Bounds on what the numbers on the command line may ask for, checked before anything is
// generated or allocated: memory and time grow with the frames scored and the samples made.
constexpr double kMaxSyntheticSeconds = 600.0;  // 600k truth samples at 1000 Hz, ~40 MB
constexpr double kMaxDisplayHz = 1000.0;
constexpr double kMaxLatencyMs = 1000.0;
constexpr double kMaxFramesScored = 1e6;        // ~200 MB of frame poses per predictor

// A finite number in [low, high] (low excluded when `open`), checked on the option's text while
// the command line is parsed, so the message names the option (CLI11's PositiveNumber lets NaN
// through: every comparison with it is false).
CLI::Validator finiteIn(double low, double high, bool open, const char* unit) {
    return CLI::Validator(
        [=](std::string& text) -> std::string {
            // from_chars: the whole text, as written (no locale, no leading space or '+').
            double v = 0.0;
            const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), v);
            const bool number = !text.empty() && error == std::errc() && end == text.data() + text.size();
            if (number && std::isfinite(v) && (open ? v > low : v >= low) && v <= high) return {};
            char message[160];
            std::snprintf(message, sizeof message, "must be a number in %s%g, %g] %s, got ", open ? "(" : "[", low,
                          high, unit);
            return message + printable(text, 40);
        },
        "");
}

// A trace is scored from warm-up to its end at the display rate: a trace whose samples lie far
// apart (two samples 1e6 s apart) would ask for billions of frames. Checked before scoring.
void checkScoredSpan(const std::string& source, const Trace& measured, const Trace& truth, double displayHz) {
    const double span = std::min(measured.back().t, truth.back().t) - std::max(measured.front().t, truth.front().t);
    if (!(span * displayHz <= kMaxFramesScored)) {
        char text[200];
        std::snprintf(text, sizeof text, ": spans %g s, %g frames at %g Hz; at most %g frames are scored "
                      "(use a shorter trace or a lower --display-hz)", span, span * displayHz, displayHz, kMaxFramesScored);
        throw std::runtime_error(printable(source, 120) + text);
    }
}

// A trace that gives no motion to score: fewer than two samples, or all at one time. `file`
// is the one named: the truth trace is checked on its own, not blamed on the measured one.
void checkHasSpan(const std::string& file, const Trace& trace) {
    if (trace.size() < 2)
        throw std::runtime_error(printable(file, 120) + ": needs at least 2 samples, has " + std::to_string(trace.size()));
    if (!(trace.back().t > trace.front().t)) {
        char text[100];
        std::snprintf(text, sizeof text, ": all %zu samples are at time %g; a trace must span some time", trace.size(),
                      trace.front().t);
        throw std::runtime_error(printable(file, 120) + text);
    }
}

struct Row {
    std::string predictor;
    Deflect deflect;
    ErrorStats stats;
    double updateNs;
};

// What an adaptive predictor learnt over the trace: its noise levels at the end, and the
// spread of the process-noise scale while it ran (sampled at every update).
struct Adapted {
    std::string predictor;
    KalmanNoiseLevels last;
    double scaleP5 = 0.0, scaleMedian = 0.0, scaleP95 = 0.0;
};

std::optional<Adapted> adaptedNoise(const Predictor& prototype, const Trace& measured) {
    auto p = prototype.clone();
    auto* kalman = dynamic_cast<KalmanPredictor*>(p.get());
    if (!kalman || !kalman->options().adaptive) return std::nullopt;
    kalman->reset();
    std::vector<double> scales;
    scales.reserve(measured.size());
    for (const auto& s : measured) {
        kalman->update(s);
        scales.push_back(kalman->noiseLevels().orientationScale);
    }
    std::sort(scales.begin(), scales.end());
    auto at = [&](double f) { return scales[std::size_t(f * double(scales.size() - 1))]; };
    return Adapted{std::string(prototype.name()), kalman->noiseLevels(), at(0.05), at(0.5), at(0.95)};
}

std::string sweepCsv(const std::vector<std::unique_ptr<Predictor>>& predictors, const std::vector<Deflect>& deflects,
                     const Trace& measured, const Trace& truth, const TwoStepConfig& base, const Intrinsics& k) {
    // Wide layout (one column per predictor/deflection) so gnuplot can plot columns directly.
    std::string out = "latency_ms";
    for (const auto& p : predictors)
        for (Deflect d : deflects)
            out += "," + std::string(p->name()) + (d == Deflect::None ? "" : "+" + std::string(deflectName(d)));
    out += "\n";
    for (int ms = 0; ms <= 100; ms += 5) {
        throwIfInterrupted();
        TwoStepConfig c = base;
        c.latency = ms * 1e-3;
        out += std::to_string(ms);
        for (const auto& p : predictors) {
            const auto frames = simulateTwoStep(*p, measured, truth, c);
            for (Deflect d : deflects) {
                char buf[32];
                std::snprintf(buf, sizeof buf, ",%.5f", summarize(frames, d, k).meanDeg);
                out += buf;
            }
        }
        out += "\n";
    }
    return out;
}

void runTrack(const TrackOptions& o) {
    const bool synthetic = o.synthetic > 0.0;  // 0: not given (the option's check refuses 0 given)
    if (o.trace.empty() == !synthetic)
        throw std::runtime_error("track: give exactly one of --trace FILE or --synthetic SECONDS");
    const Intrinsics k = parseIntrinsics(o.size, o.fovDeg);
    // Outputs are written last; a folder that is not there is noticed before the work.
    for (const std::string& out : {o.json, o.sweepCsv})
        if (!out.empty()) checkWritable(out);
    if (!o.writeTraces.empty()) checkWritable(o.writeTraces + "-measured.path");
    auto predictors = selectPredictors(o.predictors);
    const auto deflects = selectDeflects(o.deflects);

    // Every file (the traces written, the JSON, the CSV) appears only if the whole run succeeds.
    OutputBatch outputs;
    Trace measured, truth;
    std::string source, truthSource;
    if (synthetic) {
        SyntheticTraces traces;
        if (o.motion != "seated") {
            ActivityParams params;
            try {
                params.activity = parseActivity(o.motion);
            } catch (const std::invalid_argument&) {
                throw std::runtime_error("--motion `" + o.motion + "`: expected seated, walk or scan");
            }
            params.duration = o.synthetic;
            params.seed = o.seed;
            traces = generateActivityMotion(params);
            source = ActivityModel(params).describe();
        } else {
            HeadMotionParams params;
            params.duration = o.synthetic;
            params.seed = o.seed;
            traces = generateHeadMotion(params);
            source = HeadMotionModel(params).describe();
        }
        measured = std::move(traces.measured);
        truth = std::move(traces.truth);
        truthSource = "the noise-free model sampled at 1000 Hz";
        if (!o.writeTraces.empty()) {
            outputs.addText(o.writeTraces + "-measured.path",
                            formatAnimationPath(measured, "measured (noisy) trace; " + source));
            // Truth at 240 Hz keeps the shipped file small; slerp between samples 4 ms apart is
            // within 0.01 deg of the model on min-jerk turns.
            Trace truth240;
            for (double t = 0.0; t <= o.synthetic + 1e-9; t += 1.0 / 240.0) truth240.push_back(sampleAt(truth, t));
            outputs.addText(o.writeTraces + "-truth.path", formatAnimationPath(truth240, "truth trace (240 Hz); " + source));
        }
    } else {
        measured = readTrace(o.trace);
        checkHasSpan(o.trace, measured);
        source = o.trace;
        if (o.truth.empty()) {
            truth = measured;
            truthSource = "NONE GIVEN: the measured trace is used as truth (its noise counts as error)";
        } else {
            truth = readTrace(o.truth);
            checkHasSpan(o.truth, truth);
            truthSource = o.truth;
        }
        checkScoredSpan(o.trace, measured, truth, o.displayHz);
    }

    TwoStepConfig config;
    config.latency = o.latencyMs * 1e-3;
    config.reread = o.rereadMs * 1e-3;
    config.displayHz = o.displayHz;

    std::printf("strata track: %s\n", source.c_str());
    std::printf("  measured: %zu samples over %.3f s; truth: %s\n", measured.size(),
                measured.back().t - measured.front().t, truthSource.c_str());
    std::printf("  latency %.1f ms, re-read %.1f ms before display, display %.0f Hz, view %dx%d at %.0f deg "
                "horizontal FOV\n",
                o.latencyMs, std::min(o.rereadMs, o.latencyMs), o.displayHz, k.width, k.height, o.fovDeg);

    std::vector<Row> rows;
    std::vector<Adapted> adapted;
    for (const auto& p : predictors) {
        throwIfInterrupted();  // between predictors: nothing is written before the end
        if (auto a = adaptedNoise(*p, measured)) adapted.push_back(*a);
        const auto frames = simulateTwoStep(*p, measured, truth, config);
        if (frames.empty()) {
            // The truth names itself when it is what ends before the first scored frame.
            const bool truthShort = !o.truth.empty() && truth.back().t - truth.front().t < measured.back().t - measured.front().t;
            throw std::runtime_error(printable(truthShort ? o.truth : source, 120) +
                                     ": too short to score any frame (warm-up 0.5 s plus latency)");
        }
        const double ns = measureUpdateNs(*p, measured);
        for (Deflect d : deflects) rows.push_back(Row{std::string(p->name()), d, summarize(frames, d, k), ns});
    }

    std::printf("  frames scored: %zu\n\n", rows.front().stats.frames);
    std::printf("%-12s %-11s %9s %9s %9s %9s %10s\n", "predictor", "deflect", "mean_deg", "p95_deg", "max_deg",
                "mean_mm", "update_ns");
    for (const auto& r : rows)
        std::printf("%-12s %-11s %9.4f %9.4f %9.4f %9.3f %10.1f\n", r.predictor.c_str(),
                    std::string(deflectName(r.deflect)).c_str(), r.stats.meanDeg, r.stats.p95Deg, r.stats.maxDeg,
                    r.stats.meanMm, r.updateNs);
    std::printf("\nshift: angles include the uncorrected roll and the pan/scroll approximation (upper bound over 9 "
                "probe rays); position error is not correctable by a 2D deflection.\n");
    std::printf("update_ns: wall time per update(), the fastest of >= 3 passes over the measured trace.\n");
    for (const auto& a : adapted)
        std::printf("%s adapted: measurement noise %.4f deg, %.3f mm; orientation process noise %.3g rad^2/s^5 "
                    "(x%.3g of the default; over the trace x%.3g median, x%.3g-x%.3g p5-p95), position x%.3g; "
                    "mean NIS/dim %.2f\n",
                    a.predictor.c_str(), radToDeg(a.last.orientationSigma), a.last.positionSigma * 1e3,
                    a.last.orientationProcess, a.last.orientationScale, a.scaleMedian, a.scaleP5, a.scaleP95,
                    a.last.positionScale, a.last.orientationNis);

    if (!o.json.empty()) {
        nlohmann::ordered_json j;
        j["latency_ms"] = o.latencyMs;
        j["rows"] = nlohmann::ordered_json::array();
        for (const auto& r : rows)
            j["rows"].push_back({{"predictor", r.predictor},
                                 {"deflect", std::string(deflectName(r.deflect))},
                                 {"mean_deg", r.stats.meanDeg},
                                 {"p95_deg", r.stats.p95Deg},
                                 {"max_deg", r.stats.maxDeg},
                                 {"mean_mm", r.stats.meanMm},
                                 {"update_ns", r.updateNs}});
        j["adapted"] = nlohmann::ordered_json::array();
        for (const auto& a : adapted)
            j["adapted"].push_back({{"predictor", a.predictor},
                                    {"orientation_sigma_deg", radToDeg(a.last.orientationSigma)},
                                    {"position_sigma_mm", a.last.positionSigma * 1e3},
                                    {"orientation_process", a.last.orientationProcess},
                                    {"position_process", a.last.positionProcess},
                                    {"orientation_scale", a.last.orientationScale},
                                    {"position_scale", a.last.positionScale},
                                    {"orientation_scale_p5", a.scaleP5},
                                    {"orientation_scale_median", a.scaleMedian},
                                    {"orientation_scale_p95", a.scaleP95},
                                    {"orientation_nis", a.last.orientationNis}});
        outputs.addText(o.json, j.dump(2) + "\n");
    }
    if (!o.sweepCsv.empty()) outputs.addText(o.sweepCsv, sweepCsv(predictors, deflects, measured, truth, config, k));
    throwIfInterrupted();
    outputs.commit();
}

}  // namespace

void registerTrackCommand(CLI::App& app) {
    auto opts = std::make_shared<TrackOptions>();
    CLI::App* sub = app.add_subcommand(
        "track", "Replay a head-pose trace through the predictors (two-step prediction, image deflection) and "
                 "report the viewing error and update cost");
    auto* trace = sub->add_option("--trace", opts->trace,
                                  "measured trace: animation path (time px py pz qx qy qz qw) or Wu et al. CSV");
    sub->add_option("--truth", opts->truth, "truth trace (default: the measured trace itself)")->needs(trace);
    auto* synthetic = sub->add_option("--synthetic", opts->synthetic,
                                      "generate SECONDS of synthetic head motion instead of reading a trace")
                          ->check(finiteIn(0.0, kMaxSyntheticSeconds, true, "s"));
    trace->excludes(synthetic);
    // CLI11 reads "-1" into an unsigned seed as 2^64-1; a seed is refused rather than wrapped.
    sub->add_option("--seed", opts->seed, "seed of the synthetic head motion")
        ->capture_default_str()
        ->needs(synthetic)
        ->check([](const std::string& text) {
            return text.find('-') == std::string::npos ? std::string() : "must be a non-negative integer, got " + text;
        });
    sub->add_option("--motion", opts->motion,
                    "with --synthetic: seated (turns, sway, tremor; IMU-like 120 Hz sensor), walk or scan "
                    "(tracking/activity_motion.hpp; camera-like 90 Hz sensor)")
        ->capture_default_str()
        ->needs(synthetic);
    sub->add_option("--write-traces", opts->writeTraces,
                    "with --synthetic: also write PREFIX-measured.path and PREFIX-truth.path (240 Hz)")
        ->needs(synthetic);
    sub->add_option("--latency-ms", opts->latencyMs, "frame start to display")
        ->capture_default_str()
        ->check(finiteIn(0.0, kMaxLatencyMs, false, "ms"));
    sub->add_option("--reread-ms", opts->rereadMs, "second tracker read before display")
        ->capture_default_str()
        ->check(finiteIn(0.0, kMaxLatencyMs, false, "ms"));
    sub->add_option("--display-hz", opts->displayHz, "frames scored per second")
        ->capture_default_str()
        ->check(finiteIn(0.0, kMaxDisplayHz, true, "Hz"));
    sub->add_option("--predictor", opts->predictors, "none,cv,desp,kalman (adaptive),kalman-fixed,kalman-cv or all")->capture_default_str();
    sub->add_option("--deflect", opts->deflects, "none,shift,homography or all")->capture_default_str();
    sub->add_option("--size", opts->size, "view size for the deflection (WIDTHxHEIGHT)")->capture_default_str();
    sub->add_option("--fov-deg", opts->fovDeg, "horizontal field of view")->capture_default_str();
    sub->add_option("--json", opts->json, "write the table as JSON");
    sub->add_option("--sweep-csv", opts->sweepCsv, "write mean error against latency 0..100 ms as CSV");
    sub->callback([opts] { runTrack(*opts); });
}

}  // namespace strata
