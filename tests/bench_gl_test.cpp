// `strata bench` output against the JSON contract of DESIGN.md.
#include "gl_test_support.hpp"

#include "bench/bench.hpp"
#include "scene/builtin_scenes.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace strata;

namespace {

void requireNumber(const nlohmann::json& j, const char* key) {
    INFO(key);
    REQUIRE(j.contains(key));
    REQUIRE(j[key].is_number());
    CHECK(std::isfinite(j[key].get<double>()));
}

}  // namespace

TEST_CASE("bench JSON has every contract field, finite, and the reference has zero error") {
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
        if (m["id"] == "abuffer") {
            CHECK(m["rmse"] == 0.0);
            CHECK(m["max_abs_error"] == 0.0);
            CHECK(m["robustness_ratio"] == 1.0);
        }
        if (m["id"] == "blend-unsorted") CHECK(m["rmse"].get<double>() > 0.01);
    }
    CHECK(report.coplanarityProbability == 0.0);
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
    BenchReport report = runBench(scene, options);
    CHECK(report.coplanarityProbability == 1.0);
    REQUIRE(report.modes.size() == 1);  // the reference runs but is listed only when asked for
    CHECK(report.modes[0].id == "blend-sorted");
}

TEST_CASE("bench rejects an unknown technique with the list of known ones") {
    test::glContext();
    GpuScene scene(makeLayersScene(1));
    BenchOptions options;
    options.modes = {"no-such-mode"};
    options.size = {8, 8};
    CHECK_THROWS_WITH_AS(runBench(scene, options), doctest::Contains("known: blend-unsorted"), std::invalid_argument);
}
