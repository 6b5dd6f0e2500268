// The bench report page (bench/report_page.hpp) on a report whose figures are set, not measured:
// which rows are on the Pareto front, what the verdict says, what the chart is fed, and that the
// page names every file of the folder's layout, escapes what it quotes and names each row's
// reference. The page in a browser is tests/report_browser_test.sh.
#include "bench/report_page.hpp"

#include <doctest/doctest.h>

#include <algorithm>

using namespace strata;

namespace {

BenchMode row(const std::string& id, const std::string& family, double ms, double rmse,
              const std::string& reference = "abuffer") {
    BenchMode m;
    m.id = id;
    m.family = family;
    m.reference = reference;
    m.msMedian = ms;
    m.rmse = rmse;
    m.psnr = rmse > 0.0 ? -20.0 * std::log10(rmse) : 100.0;
    m.maxAbsError = rmse * 4.0;
    m.fragmentsTotal = m.fragmentsCaptured = 1000;
    m.passes = 2;
    return m;
}

// floor 0.5 ms; fast 0.8 ms (loose); mid 2 ms (better); slow 3 ms (worse than mid: dominated);
// exact 5 ms; exact-slow 6 ms (dominated); a volumetric row fast and exact against its own
// reference; an overflowing buffer; a peeling that loses coplanar fragments.
BenchReport sampleReport() {
    BenchReport r;
    r.scene = "builtin:<sample> & co";
    r.size = {64, 40};
    r.frames = 3;
    r.device.renderer = "llvmpipe";
    r.modes.push_back(row("abuffer", "reference", 5.0, 0.0));
    r.modes.push_back(row("floor", "floor", 0.5, 0.2));
    r.modes.push_back(row("fast", "baseline", 0.8, 0.1));
    r.modes.push_back(row("mid", "approximate", 2.0, 0.01));
    r.modes.push_back(row("slow", "approximate", 3.0, 0.05));
    r.modes.push_back(row("exact-slow", "buffer", 6.0, 0.0));
    r.modes.push_back(row("ll-volume", "volumetric", 0.4, 0.0, "abuffer-volume"));
    BenchMode over = row("bun", "peeling", 1.5, 0.02);
    over.overflowed = true;
    over.fragmentsCaptured = 900;
    r.modes.push_back(over);
    BenchMode lost = row("f2b", "peeling", 4.0, 0.011);
    lost.fragmentsCaptured = 950;
    lost.fragmentsDropped = 50;
    r.modes.push_back(lost);
    r.pixelsByLargestLayer[1] = 80;
    r.pixelsByLargestLayer[2] = 20;
    r.coplanarityProbability = 0.2;
    return r;
}

std::vector<std::string> ids(const BenchReport& r, const std::vector<std::size_t>& rows) {
    std::vector<std::string> out;
    for (std::size_t i : rows) out.push_back(r.modes[i].id);
    return out;
}

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
    return n;
}

}  // namespace

TEST_CASE("report: the Pareto front holds the rows nothing beats, by time, on the report's reference only") {
    const BenchReport r = sampleReport();
    // fast (0.8, 0.1) < bun (1.5, 0.02) < mid (2, 0.01) < abuffer (5, 0); slow, f2b and exact-slow
    // are beaten; the floor and the volumetric row do not compete.
    CHECK(ids(r, paretoFront(r)) == std::vector<std::string>{"fast", "bun", "mid", "abuffer"});
    // A tie in both figures: neither beats the other, both are on the front.
    BenchReport tie = r;
    tie.modes.push_back(row("twin", "buffer", 5.0, 0.0));
    const auto front = ids(tie, paretoFront(tie));
    CHECK(std::count(front.begin(), front.end(), "twin") == 1);
    CHECK(std::count(front.begin(), front.end(), "abuffer") == 1);
}

TEST_CASE("report: the verdict names the fastest exact row, the most accurate near the floor, and what was lost") {
    const std::vector<std::string> v = reportVerdict(sampleReport());
    REQUIRE(v.size() == 4);
    // ll-volume is faster and exact, but against another model: abuffer is the answer.
    CHECK(v[0] == "Fastest exact technique: abuffer, 5.00 ms (10.00x the floor).");
    // Within 2x the floor (1 ms) only fast runs.
    CHECK(v[1] == "Most accurate within 2x the floor (1.00 ms): fast, 20.0 dB at 0.80 ms (1.60x the floor).");
    CHECK(v[2] == "Overflowed: bun kept 900 of 1000 fragments.");
    CHECK(v[3] == "Fragments counted and not kept: f2b kept 950 of 1000.");

    BenchReport none = sampleReport();
    none.modes.erase(none.modes.begin() + 1);  // no floor
    for (auto& m : none.modes) m.maxAbsError = std::max(m.maxAbsError, 0.5);
    const std::vector<std::string> w = reportVerdict(none);
    CHECK(w[0].find("No technique measured here is exact") == 0);
    CHECK(w[1].find("The floor was not measured") == 0);
}

TEST_CASE("report: the chart's data places exact rows a decade below the rest and lists the front in order") {
    const BenchReport r = sampleReport();
    const TradeoffChartData chart = tradeoffChartData(r);
    // The smallest non-zero RMSE is 0.01 (decade -2), but the exact row sits at most at 1e-7.
    CHECK(chart.exactRmse == doctest::Approx(1e-7));
    CHECK(chart.yTics.find("\"exact\" 1e-07") == 0);
    CHECK(chart.families == "reference floor baseline approximate buffer volumetric peeling");
    const std::string points = chart.datablocks.substr(0, chart.datablocks.find("$front"));
    CHECK(count(points, "\n") == r.modes.size() + 2);                   // header, rows, EOD
    CHECK(points.find("0.4 1e-07 5 \"ll-volume\" 1") != std::string::npos);  // other reference: flagged
    CHECK(points.find("5 1e-07 0 \"abuffer\" 0") != std::string::npos);
    const std::string front = chart.datablocks.substr(chart.datablocks.find("$front"));
    CHECK(front.find("\"fast\"") < front.find("\"bun\""));
    CHECK(front.find("\"mid\"") < front.find("\"abuffer\""));
    CHECK(front.find("\"slow\"") == std::string::npos);

    // Very small errors push the exact level down with them.
    BenchReport tiny = r;
    tiny.modes[2].rmse = 3e-10;
    CHECK(tradeoffChartData(tiny).exactRmse == doctest::Approx(1e-11));
}

TEST_CASE("report: the page names every file of the folder, each row's reference, and escapes what it quotes") {
    const BenchReport r = sampleReport();
    ReportPageText text;
    text.title = "Report <1>";
    text.date = "2026-11-25";
    text.thumbnailSize = {32, 20};
    text.imageSize = {64, 40};
    const std::string html = reportHtml(r, text);
    CHECK(html.rfind("<!DOCTYPE html>", 0) == 0);
    for (const auto& m : r.modes) {
        CAPTURE(m.id);
        CHECK(count(html, "src=\"thumbs/" + m.id + ".png\"") == 1);
        CHECK(count(html, "src=\"thumbs/" + m.id + "-error.png\"") == 1);
        CHECK(count(html, "href=\"images/" + m.id + ".png\"") == 1);
        CHECK(count(html, "href=\"errors/" + m.id + ".png\"") == 1);
        CHECK(count(html, "id=\"m-" + m.id + "\"") == 1);   // the table's rows link to the cards
        CHECK(count(html, "href=\"#m-" + m.id + "\"") == 1);
    }
    for (const char* file : {"src=\"exact.png\"", "src=\"heatmap.png\"", "src=\"chart.svg\"", "href=\"bench.json\"",
                             "href=\"bench.csv\"", "href=\"README.md\""})
        CHECK(count(html, file) == 1);
    CHECK(count(html, "<tr><td><a href=\"#m-") == r.modes.size());
    CHECK(html.find("error against <code>abuffer-volume</code> (itself") == std::string::npos);
    CHECK(html.find("error against <code>abuffer-volume</code>, exact") != std::string::npos);  // ll-volume's card
    CHECK(html.find("builtin:&lt;sample&gt; &amp; co") != std::string::npos);
    CHECK(html.find("<sample>") == std::string::npos);
    CHECK(html.find("Report &lt;1&gt;") != std::string::npos);
    CHECK(count(html, "<h3>") == 7);  // one section per family
    CHECK(html.find("width=\"32\" height=\"20\"") != std::string::npos);
    CHECK(html.find("http") == std::string::npos);  // nothing from the network

    // Without gnuplot the chart's place says why.
    text.chartNote = "The chart was not drawn: gnuplot was not found";
    const std::string noChart = reportHtml(r, text);
    CHECK(noChart.find("chart.svg") == std::string::npos);
    CHECK(noChart.find("gnuplot was not found") != std::string::npos);
    CHECK(reportMarkdown(r, text).find("chart.svg") == std::string::npos);
    CHECK(reportMarkdown(r, ReportPageText{}).find("![speed against accuracy](chart.svg)") != std::string::npos);

    CHECK(htmlEscape("a<b>&\"'") == "a&lt;b&gt;&amp;&quot;&#39;");
}
