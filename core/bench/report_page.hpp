#pragma once
// The bench report as people look at it (`strata demo`, `strata bench --report DIR`): a
// self-contained HTML page and a Markdown summary of one BenchReport, and the figures both draw
// on (the speed/accuracy Pareto front, a verdict from the numbers, the chart's data). Text only:
// report_folder.hpp writes the files the page refers to. The folder's layout, which the page's
// links rest on:
//   index.html, README.md, bench.json, bench.csv
//   exact.png           the reference's first frame      heatmap.png  its coplanarity heatmap
//   chart.svg           the speed/accuracy chart (absent when gnuplot was not found)
//   images/ID.png       each technique's first frame      errors/ID.png  its error map
//   thumbs/ID.png       both reduced for the contact sheet thumbs/ID-error.png
#include "bench/bench.hpp"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace strata {

// What the page says beyond the report's numbers.
struct ReportPageText {
    std::string title = "Strata bench report";
    std::string description;  // a paragraph about the scene (plain text)
    std::string date;         // when the run was made, as shown ("2026-11-25 22:40 UTC")
    std::string command;      // the command that produced it
    std::string chartNote;    // empty when chart.svg was drawn, else why not (shown instead)
    glm::ivec2 thumbnailSize{0, 0};  // every thumbnail's size in pixels
    glm::ivec2 imageSize{0, 0};      // exact.png's and heatmap.png's size
    std::string exactReference;      // the technique exact.png shows (empty: the report's reference)
};

// The error a technique row's error map shows as full red (ErrorMap's scale): per channel, linear.
inline constexpr float kReportErrorScale = 0.05f;

// The rows on the speed/accuracy Pareto front, as indices into report.modes by GPU time: no
// other row is at least as fast and at least as accurate (RMSE) and better in one. Only rows
// measured against the report's reference compete (a volumetric row's RMSE is against another
// model); the floor, which draws no transparency model, does not.
std::vector<std::size_t> paretoFront(const BenchReport& report);

// Sentences drawn from the numbers: the fastest exact technique (every fragment kept, nothing
// overflowed, no channel off by more than 1/255), the most accurate within 2x the floor, and what
// overflowed or dropped fragments. Each names its figures.
std::vector<std::string> reportVerdict(const BenchReport& report);

// The chart's input for scripts/plots/tradeoff.gp: the $points and $front datablocks, the RMSE
// an exact row (RMSE 0) is drawn at, a decade below the lowest decade of any other row and at
// most 1e-7, and the y axis' labels (gnuplot's "set ytics (...)" list).
struct TradeoffChartData {
    std::string datablocks;
    std::string families;  // space-separated, in the order of the points' family index
    double exactRmse = 1e-7;
    std::string yTics;
};
TradeoffChartData tradeoffChartData(const BenchReport& report);

// The page: self-contained (no network, no framework; a few lines of plain script sort the table
// and report images that failed to load) and valid HTML5.
std::string reportHtml(const BenchReport& report, const ReportPageText& text);

// The Markdown summary beside it: the table, the verdict and the two images that matter.
std::string reportMarkdown(const BenchReport& report, const ReportPageText& text);

// `text` safe inside HTML element content and quoted attributes.
std::string htmlEscape(const std::string& text);

}  // namespace strata
