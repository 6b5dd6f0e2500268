#pragma once
// Writes a bench report folder (report_page.hpp's layout) as one output batch: each technique's
// first frame, its error map and their thumbnails are written as the bench produces them (no
// image is held past its callback), then the chart (gnuplot, scripts/plots/tradeoff.gp), the
// page, the Markdown summary, the JSON and the CSV. Everything appears when the batch commits.
#include "bench/bench.hpp"
#include "bench/report_page.hpp"
#include "io/atomic_file.hpp"

#include <filesystem>
#include <optional>
#include <string>

namespace strata {

class ReportFolder {
public:
    // Creates `folder` and its image folders in `outputs` (removed again unless it commits).
    // `imageSize`: the bench's frame size, for the thumbnails' size.
    ReportFolder(OutputBatch& outputs, std::filesystem::path folder, glm::ivec2 imageSize);

    // Hooks `options`' firstFrame and coplanarityHeatmap callbacks; the folder must outlive the
    // bench run.
    void attach(BenchOptions& options);

    // Writes everything that needs the whole report. `text`'s sizes and chart note are filled in
    // here. Returns a warning to show when something was left out (the chart, without gnuplot),
    // else an empty string. Throws std::runtime_error when gnuplot fails.
    std::string finish(const BenchReport& report, ReportPageText text);

    glm::ivec2 thumbnailSize() const { return thumbnailSize_; }

private:
    void addFrame(const std::string& id, const Image& frame, const Image& reference);

    OutputBatch& outputs_;
    std::filesystem::path folder_;
    int thumbnailFactor_ = 1;
    glm::ivec2 imageSize_{0}, thumbnailSize_{0};
    std::optional<Image> exact_;  // the first frame of the report's reference, for exact.png
    std::string exactId_;
};

// The folder of gnuplot scripts: $STRATA_PLOT_DIR if set, else the source tree's scripts/plots.
std::filesystem::path plotScriptFolder();

}  // namespace strata
