// `strata bench` output against the JSON contract of DESIGN.md.
#include "gl_test_support.hpp"

#include "bench/advisor.hpp"
#include "bench/bench.hpp"
#include "io/interrupt.hpp"
#include "reference/raycast.hpp"
#include "scene/builtin_scenes.hpp"

#include <glm/gtc/quaternion.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <map>

using namespace strata;

namespace {

void requireNumber(const nlohmann::json& j, const char* key) {
    INFO(key);
    REQUIRE(j.contains(key));
    REQUIRE(j[key].is_number());
    CHECK(std::isfinite(j[key].get<double>()));
}

// One 8-bit step: the contract for exact techniques (abuffer_gl_test.cpp holds abuffer to it).
constexpr float kTolerance = 1.0f / 255.0f;

}  // namespace

TEST_CASE("bench JSON has every contract field, finite, and counts every fragment") {
    test::glContext();
    GpuScene scene(makeLayersScene(4));
    BenchOptions options;
    options.sceneName = "builtin:layers:4";
    options.size = {24, 16};
    options.frames = 3;
    options.warmupFrames = 1;
    BenchReport report = runBench(scene, options);
    nlohmann::json j = nlohmann::json::parse(benchToJson(report).dump());

    CHECK(j["scene"] == "builtin:layers:4");
    CHECK(j["size"] == nlohmann::json::array({24, 16}));
    CHECK(j["frames"] == 3);
    for (const char* k : {"vendor", "renderer", "version"}) CHECK(j["device"][k].is_string());
    CHECK(j["reference"] == "abuffer");
    requireNumber(j, "coplanarity_probability");
    requireNumber(j, "coplanarity_one_per_layer_robustness");
    REQUIRE(j["modes"].is_array());
    CHECK(j["modes"].size() == techniqueRegistry().size());
    for (const auto& m : j["modes"]) {
        CAPTURE(m["id"].get<std::string>());
        CHECK(m["id"].is_string());
        CHECK(m["robust"].is_boolean());
        CHECK(m["handles_coplanarity"].is_boolean());
        CHECK(m["overflowed"].is_boolean());
        for (const char* k : {"ms_median", "ms_p95", "passes", "bytes", "fragments_total", "fragments_captured",
                              "robustness_ratio", "rmse", "psnr", "max_abs_error"})
            requireNumber(m, k);
        CHECK(m["fragments_total"] == 4 * 24 * 16 * 3);
        // The span from the first GPU stamp to the last holds every pass of the frame: at least
        // the longest one (the passes are the median frame's only approximately, so no more).
        requireNumber(m, "frame_span_ms_median");
        double longestPass = 0.0;
        for (const auto& [name, ms] : m["pass_ms_median"].items()) longestPass = std::max(longestPass, ms.get<double>());
        CHECK(m["frame_span_ms_median"].get<double>() > 0.0);
        CHECK(m["frame_span_ms_median"].get<double>() >= 0.9 * longestPass);
        // abuffer's own error is against itself, zero by definition: the test below checks the
        // reference against the CPU ray cast instead.
        if (m["id"] == "abuffer") CHECK(m["robustness_ratio"] == 1.0);
        if (m["id"] == "blend-unsorted") CHECK(m["rmse"].get<double>() > 0.01);
    }
    CHECK(report.coplanarityProbability == 0.0);
}

TEST_CASE("bench --wall times the same frames untimed: a wall time per technique, null without") {
    test::glContext();
    GpuScene scene(makeLayersScene(4));
    BenchOptions options;
    options.sceneName = "builtin:layers:4";
    options.modes = {"abuffer", "f2b", "dual"};
    options.size = {24, 16};
    options.frames = 2;
    options.warmupFrames = 1;
    const BenchReport timedOnly = runBench(scene, options);
    options.wallFrames = true;
    const BenchReport both = runBench(scene, options);
    const nlohmann::json without = benchToJson(timedOnly), with = benchToJson(both);
    REQUIRE(with["modes"].size() == 3);
    for (std::size_t i = 0; i < 3; ++i) {
        CAPTURE(with["modes"][i]["id"].get<std::string>());
        CHECK(without["modes"][i]["wall_ms_median"].is_null());
        requireNumber(with["modes"][i], "wall_ms_median");
        CHECK(with["modes"][i]["wall_ms_median"].get<double>() > 0.0);
        // The untimed frames add nothing to the timed ones' counts: the same fragments captured.
        CHECK(with["modes"][i]["fragments_captured"] == without["modes"][i]["fragments_captured"]);
    }
    CHECK(benchToTable(both).find("wall ms") != std::string::npos);
    CHECK(benchToTable(timedOnly).find("wall ms") == std::string::npos);
}

TEST_CASE("bench reports coplanarity where surfaces coincide") {
    test::glContext();
    GpuScene scene(makeCoplanarScene(3));
    BenchOptions options;
    options.sceneName = "builtin:coplanar:3";
    options.modes = {"blend-sorted"};
    options.size = {16, 16};
    options.frames = 1;
    options.warmupFrames = 0;
    // The report's hooks: the heatmap of the measured frame, and each first frame with the
    // reference it was compared against (the reference row: itself).
    Image heatmap;
    options.coplanarityHeatmap = [&](const Image& h) { heatmap = h; };
    std::map<std::string, std::pair<Image, Image>> first;
    options.firstFrame = [&](const std::string& id, const Image& frame, const Image& reference) {
        first[id] = {frame, reference};
    };
    BenchReport report = runBench(scene, options);
    CHECK(report.coplanarityProbability == 1.0);
    CHECK(report.coplanarityOnePerLayerRobustness == doctest::Approx(1.0 / 3.0));
    REQUIRE(report.modes.size() == 1);  // the reference runs but is listed only when asked for
    CHECK(report.modes[0].id == "blend-sorted");

    // Every pixel with fragments holds three in one layer: Fig. 13's blue, and only bin 3 counts.
    REQUIRE(heatmap.width == 16);
    REQUIRE(heatmap.height == 16);
    std::uint64_t blue = 0;
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) blue += glm::vec3(heatmap.at(x, y)) == coplanarityColor(3);
    CHECK(blue > 0);
    CHECK(report.pixelsByLargestLayer[3] == blue);
    CHECK(report.pixelsByLargestLayer[2] == 0);
    REQUIRE(first.size() == 2);
    CHECK(first["abuffer"].first.rgba == first["abuffer"].second.rgba);
    CHECK(first["blend-sorted"].second.rgba == first["abuffer"].first.rgba);
}

TEST_CASE("bench against a supersampled reference: the reference's own row shows what one sample a pixel loses") {
    test::glContext();
    auto run = [](const std::string& spec, int supersample) {
        GpuScene scene(makeBuiltinScene(spec));
        BenchOptions options;
        options.sceneName = "builtin:" + spec;
        options.modes = {"abuffer"};
        options.size = {32, 24};
        options.frames = 1;
        options.warmupFrames = 0;
        options.referenceSupersample = supersample;
        const BenchReport report = runBench(scene, options);
        REQUIRE(report.modes.size() == 1);
        CHECK(report.referenceSupersample == supersample);
        return report.modes[0];
    };
    // One sample a pixel: the reference against itself.
    CHECK(run("cubes", 1).psnr == 100.0);
    // Full-view quads have no edge inside the view: 2x2 samples of a pixel all see the same
    // layers, so the averaged frame is the plain one.
    const BenchMode flat = run("layers:4", 2);
    CHECK(flat.psnr == 100.0);
    CHECK(flat.maxAbsError < 1e-5);
    // Cubes have edges in view: averaged, their pixels differ from one sample's.
    const BenchMode edges = run("cubes", 2);
    CHECK(edges.psnr < 60.0);
    CHECK(edges.psnr > 15.0);
    CHECK(edges.maxAbsError > 0.05);
}

TEST_CASE("bench rejects an unknown technique with the list of known ones") {
    test::glContext();
    GpuScene scene(makeLayersScene(1));
    BenchOptions options;
    options.modes = {"no-such-mode"};
    options.size = {8, 8};
    CHECK_THROWS_WITH_AS(runBench(scene, options), doctest::Contains("known: blend-unsorted"), std::invalid_argument);
}

// Every error the bench reports is measured against its reference frames, so they are checked
// against something independent of the GPU: the CPU ray cast of the same camera.
TEST_CASE("bench's reference frames equal the CPU ray cast, with a fixed camera and along a path") {
    test::glContext();
    SUBCASE("builtin:layers:4, fixed camera: every pixel the closed-form composite of 4 layers") {
        GpuScene scene(makeLayersScene(4));
        BenchOptions options;
        options.modes = {"blend-sorted"};
        options.size = {24, 16};
        options.frames = 2;
        options.warmupFrames = 0;
        std::map<int, int> seen;  // frame -> reference frames checked
        Image cpu = raycastReference(scene.scene(), scene.objects(), defaultCamera(scene.scene(), scene.objects()),
                                     options.size.x, options.size.y);
        options.referenceFrame = [&](int frame, const Image& reference) {
            CAPTURE(frame);
            ImageDifference d = compareImages(reference, cpu, kTolerance);
            CHECK(d.maxAbsError <= kTolerance);
            CHECK(d.pixelsOver == 0);
            ++seen[frame];
        };
        runBench(scene, options);
        CHECK(seen == std::map<int, int>{{0, 1}, {1, 1}});
    }
    SUBCASE("builtin:shells:2 along a camera path: each frame's reference is rendered for that frame's camera") {
        GpuScene scene(makeShellsScene(2, false));
        Camera base = defaultCamera(scene.scene(), scene.objects());
        CameraPath path;  // sideways by 0.6 m over one second: the spheres move across the view
        path.add(0.0, base.position, base.orientation);
        path.add(1.0, base.position + glm::vec3(0.6f, 0.2f, 0.0f), base.orientation);
        BenchOptions options;
        options.modes = {"blend-sorted"};
        options.size = {32, 24};
        options.frames = 3;  // t = 0, 0.5, 1 (spread evenly over the path)
        options.warmupFrames = 0;
        options.cameraPath = path;
        std::vector<Image> cpu;
        for (double t : {0.0, 0.5, 1.0}) {
            Camera c = cameraAt(path, t, base);
            c.fitClipPlanes(scene.bounds());
            cpu.push_back(raycastReference(scene.scene(), scene.objects(), c, options.size.x, options.size.y));
        }
        // The frames differ by far more than the tolerance, so a reference for the wrong camera
        // cannot pass.
        REQUIRE(compareImages(cpu[0], cpu[1], kTolerance).pixelsOver > 50);
        REQUIRE(compareImages(cpu[1], cpu[2], kTolerance).pixelsOver > 50);
        std::map<int, int> seen;
        options.referenceFrame = [&](int frame, const Image& reference) {
            CAPTURE(frame);
            REQUIRE(frame >= 0);
            REQUIRE(frame < 3);
            // Within one 8-bit step everywhere except on the outline: the rasterizer snaps vertices
            // to its sub-pixel grid (8 bits on current hardware and llvmpipe), so a pixel centre
            // within 1/256 pixel of an outline edge may be covered on one side and not the other.
            // The (shared) outline of the two spheres crosses about 55 pixels; at most 2 may flip.
            // llvmpipe flips none. A reference for another frame's camera differs in over 250.
            ImageDifference d = compareImages(reference, cpu[std::size_t(frame)], kTolerance);
            CHECK(d.pixelsOver <= 2);
            ++seen[frame];
        };
        runBench(scene, options);
        // Rendered in the reference's own run, then again before blend-sorted's frame of each
        // camera (the bench keeps one reference frame at a time).
        CHECK(seen == std::map<int, int>{{0, 2}, {1, 2}, {2, 2}});
    }
}

TEST_CASE("bench stopped by a signal keeps exactly the techniques that completed, and says so") {
    test::glContext();
    installInterruptHandlers();
    clearInterrupt();
    GpuScene scene(makeLayersScene(3));
    BenchOptions options;
    options.sceneName = "builtin:layers:3";
    options.modes = {"abuffer", "wboit", "ll"};
    options.size = {16, 16};
    options.frames = 3;
    options.warmupFrames = 0;
    // firstFrame sees a technique once it completed; SIGTERM arrives there for wboit: abuffer and
    // wboit completed, ll never starts.
    std::vector<std::string> started;
    options.firstFrame = [&](const std::string& id, const Image&, const Image&) {
        started.push_back(id);
        if (id == "wboit") std::raise(SIGTERM);
    };
    const BenchReport report = runBench(scene, options);
    CHECK(interruptSignal() == SIGTERM);
    clearInterrupt();
    CHECK(report.interrupted);
    CHECK(report.modesPlanned == 3);
    REQUIRE(report.modes.size() == 2);
    CHECK(report.modes[0].id == "abuffer");
    CHECK(report.modes[1].id == "wboit");
    CHECK(started == std::vector<std::string>{"abuffer", "wboit"});
    CHECK(benchToJson(report)["interrupted"] == true);
    CHECK(benchToTable(report).find("INTERRUPTED: 2 of 3 techniques completed") != std::string::npos);
    // Without a signal the same run completes.
    options.firstFrame = nullptr;
    const BenchReport whole = runBench(scene, options);
    CHECK_FALSE(whole.interrupted);
    CHECK(whole.modes.size() == 3);
    CHECK(benchToJson(whole)["interrupted"] == false);
}

TEST_CASE("advise measures each configuration against the reference and recommends an exact one by default") {
    test::glContext();
    // builtin:layers:4: four quads in every pixel. ll with room for two nodes a pixel overflows and
    // drops half the layers; wboit approximates; abuffer is the reference itself.
    GpuScene scene(makeBuiltinScene("layers:4"));
    BenchOptions base;
    base.size = {32, 32};
    base.frames = 1;
    base.warmupFrames = 0;
    const std::vector<AdvisorCandidate> candidates = {{"abuffer", {}}, {"wboit", {}}, {"ll", {"capacity=2"}}};
    std::vector<AdvisorPoint> points = measureCandidates(scene, candidates, base, {});
    REQUIRE(points.size() == 3);
    std::map<std::string, const AdvisorPoint*> byLabel;
    for (const AdvisorPoint& p : points) byLabel[p.candidate.label()] = &p;
    REQUIRE(byLabel.count("ll capacity=2"));
    CHECK(byLabel["abuffer"]->reference == "abuffer");
    CHECK(byLabel["wboit"]->rmse > 1e-3);
    CHECK(byLabel["ll capacity=2"]->overflowed);
    CHECK(byLabel["ll capacity=2"]->rmse > 1e-2);
    for (const AdvisorPoint& p : points) CHECK((std::isfinite(p.frameMs) && p.frameMs > 0.0));
    markPareto(points);
    const AdvisorPick pick = recommend(points, {});
    REQUIRE(pick.index >= 0);
    CHECK(points[std::size_t(pick.index)].candidate.id == "abuffer");  // the only one within 1/255
    // With a budget no configuration can meet, the fastest; with one every configuration meets,
    // the least error (abuffer's, 0 against itself, but wboit and the overflowing ll are not 0).
    CHECK(recommend(points, {1e-9, std::nullopt}).reason.find("nothing fits") != std::string::npos);
    CHECK(points[std::size_t(recommend(points, {1e9, std::nullopt}).index)].candidate.id == "abuffer");
    // A trade limit below every default: the trades are not measured, the defaults are.
    const std::vector<AdvisorCandidate> withDefaults = {{"wboit", {}}, {"ll", {}}, {"ll", {"capacity=2"}}};
    const std::vector<AdvisorPoint> limited = measureCandidates(scene, withDefaults, base, {}, 1e-9);
    REQUIRE(limited.size() == 2);
    CHECK((limited[0].candidate.assignments.empty() && limited[1].candidate.assignments.empty()));
}

namespace {

// abuffer at 64x48, no warm-up, under a budget nothing meets (1e-6 ms), zoom 1..4, a hold of one
// frame: a reactive controller raises the zoom every frame it may.
BenchOptions unreachableBudgetRun(int frames) {
    BenchOptions options;
    options.modes = {"abuffer"};
    options.size = {64, 48};
    options.frames = frames;
    options.warmupFrames = 0;
    options.settings = resolveSettings(benchModeIds(options.modes), {});
    ZoomBudget budget;
    budget.targetMs = 1e-6;
    budget.minZoom = 1;
    budget.maxZoom = 4;
    budget.holdFrames = 1;
    options.budget = budget;
    return options;
}

}  // namespace

TEST_CASE("bench under a budget reports each frame's PSNR against the same frame without one") {
    test::glContext();
    // A budget nothing meets: the reactive controller raises the zoom every frame it may. The first
    // frame (zoom 1, geometry) equals its unconstrained render; a zoomed one loses the edges.
    GpuScene scene(makeBuiltinScene("default"));
    BenchOptions options = unreachableBudgetRun(6);
    const BenchReport report = runBench(scene, options);
    REQUIRE(report.modes.size() == 1);
    const BenchMode& m = report.modes.front();
    REQUIRE(m.framePsnr.size() == 6);
    REQUIRE(m.frameZoom.size() == 6);
    CHECK(m.frameImpostorObjects == std::vector<int>(6, 0));
    CHECK(m.frameZoom.front() == 1);
    CHECK(m.framePsnr.front() >= 60.0);
    CHECK(m.frameZoom.back() > 1);
    CHECK(m.framePsnr.back() < 40.0);
    const nlohmann::json j = benchToJson(report);
    CHECK(j["modes"][0]["budget"]["frame_psnr"].size() == 6);
    CHECK(j["modes"][0]["budget"]["frame_impostor_objects"].size() == 6);
}

TEST_CASE("bench with a pinned budget state draws every frame at that state, with each frame's PSNR") {
    test::glContext();
    // The same budget nothing meets, which raised the zoom above, now pinned at zoom 2: every
    // frame at zoom 2 and no governor. The camera holds, so every frame loses the same edges.
    GpuScene scene(makeBuiltinScene("default"));
    BenchOptions options = unreachableBudgetRun(4);
    options.budgetPin = BudgetPin{2, 0};
    const BenchReport report = runBench(scene, options);
    REQUIRE(report.modes.size() == 1);
    const BenchMode& m = report.modes.front();
    CHECK(m.frameZoom == std::vector<int>(4, 2));
    REQUIRE(m.framePsnr.size() == 4);
    CHECK(m.framePsnr.front() < 40.0);
    CHECK(m.framePsnr.back() == doctest::Approx(m.framePsnr.front()).epsilon(1e-3));
    CHECK(m.framePredictedMs == std::vector<double>(4, 0.0));
    const nlohmann::json j = benchToJson(report);
    CHECK(j["zoom_controller"] == "pinned");
    CHECK(j["budget_pin"]["zoom"] == 2);
    CHECK(j["budget_pin"]["lod_level"] == 0);
    // A level above 0 needs the LOD lever, which needs an auto LOD controller's previews; a zoom
    // above 1 the zoom lever, within the budget's largest zoom.
    options.budgetPin = BudgetPin{1, 1};
    CHECK_THROWS_WITH_AS(runBench(scene, options), doctest::Contains("needs the LOD lever"), std::invalid_argument);
    options.budgetPin = BudgetPin{5, 0};
    CHECK_THROWS_WITH_AS(runBench(scene, options), doctest::Contains("the pinned zoom 5 is above --zoom-max 4"),
                         std::invalid_argument);
    options.levers = {false, true};
    options.lodPreview = [](const Camera&, glm::ivec2, const std::vector<double>&) { return LodPreview{}; };
    options.budgetPin = BudgetPin{2, 0};
    CHECK_THROWS_WITH_AS(runBench(scene, options), doctest::Contains("needs the zoom lever"), std::invalid_argument);

    // With the LOD lever, every frame, the warm-up's included, asks LOD for the pinned level's
    // bound: the ladder's base (4 px) x 2^2 at level 2. The stand-ins themselves are LOD's
    // (none here).
    options.levers = {true, true};
    options.warmupFrames = 1;
    options.budgetPin = BudgetPin{2, 2};
    std::vector<double> asked;
    options.lod = [&](const Camera&, glm::ivec2, int, double maxErrorPx) {
        asked.push_back(maxErrorPx);
        return BenchLodFrame{};
    };
    const BenchReport withLod = runBench(scene, options);
    REQUIRE(withLod.modes.size() == 1);
    CHECK(withLod.modes.front().frameLodBoundPx == std::vector<double>(4, 16.0));
    CHECK(withLod.modes.front().frameZoom == std::vector<int>(4, 2));
    CHECK(asked == std::vector<double>(5, 16.0));
}
