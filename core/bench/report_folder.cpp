#include "bench/report_folder.hpp"

#include "io/interrupt.hpp"
#include "io/printable.hpp"
#include "io/run_program.hpp"
#include "render/error_map.hpp"

#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <stdexcept>

namespace strata {
namespace {

// Thumbnails about 240 pixels wide: two per card, cards of ~430 pixels on the page.
constexpr int kThumbnailWidth = 240;

// A gnuplot single-quoted string: a quote inside is written twice. gnuplot ends an open string
// at the end of a line and runs the next line as a command, so no control character may pass:
// in text it becomes a space; a path that holds one is refused (renaming it would write elsewhere).
std::string gnuplotString(const std::string& text, bool path = false) {
    std::string out = "'";
    for (char c : text) {
        const bool control = (unsigned char)c < 0x20 || c == 0x7f;
        if (control && path) throw std::runtime_error(text + ": a path with control characters cannot be given to gnuplot");
        out += c == '\'' ? std::string("''") : control ? std::string(" ") : std::string(1, c);
    }
    return out + "'";
}

}  // namespace

std::filesystem::path plotScriptFolder() {
    if (const char* env = std::getenv("STRATA_PLOT_DIR"); env && *env) return env;
    return STRATA_PLOT_DIR;
}

ReportFolder::ReportFolder(OutputBatch& outputs, std::filesystem::path folder, glm::ivec2 imageSize)
    : outputs_(outputs), folder_(std::move(folder)), imageSize_(imageSize) {
    thumbnailFactor_ = std::max(1, (imageSize.x + kThumbnailWidth - 1) / kThumbnailWidth);
    thumbnailSize_ = (imageSize + thumbnailFactor_ - 1) / thumbnailFactor_;
    for (const char* sub : {"images", "errors", "thumbs"}) outputs_.createFolder(folder_ / sub);
}

void ReportFolder::attach(BenchOptions& options) {
    options.firstFrame = [this](const std::string& id, const Image& frame, const Image& reference) {
        addFrame(id, frame, reference);
    };
    options.coplanarityHeatmap = [this](const Image& heatmap) { writeImage(outputs_, folder_ / "heatmap.png", heatmap); };
}

void ReportFolder::addFrame(const std::string& id, const Image& frame, const Image& reference) {
    // The top of the page shows the main reference (abuffer) when the run has it, whichever row
    // brought its frame; another reference only when no row was measured against abuffer.
    const std::string referenceId = benchReferenceOf(id);
    if (!exact_ || (exactId_ != "abuffer" && referenceId == "abuffer")) {
        exact_ = reference;
        exactId_ = referenceId;
    }
    const Image errors = errorMapImage(frame, reference, kReportErrorScale);
    writeImage(outputs_, folder_ / "images" / (id + ".png"), frame);
    writeImage(outputs_, folder_ / "errors" / (id + ".png"), errors);
    writeImage(outputs_, folder_ / "thumbs" / (id + ".png"), boxDownscale(frame, thumbnailFactor_));
    writeImage(outputs_, folder_ / "thumbs" / (id + "-error.png"), boxDownscale(errors, thumbnailFactor_));
}

std::string ReportFolder::finish(const BenchReport& report, ReportPageText text) {
    if (!exact_) throw std::runtime_error(folder_.string() + ": the bench rendered no frame to report");
    writeImage(outputs_, folder_ / "exact.png", *exact_);
    if (text.date.empty()) {
        const std::time_t now = std::time(nullptr);
        char date[32];
        std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
        text.date = date;
    }
    text.imageSize = imageSize_;
    text.exactReference = exactId_;
    text.thumbnailSize = thumbnailSize_;
    std::string warning;
    if (programOnPath("gnuplot")) {
        const TradeoffChartData chart = tradeoffChartData(report);
        const std::string script = (plotScriptFolder() / "tradeoff.gp").string();
        outputs_.add(folder_ / "chart.svg", [&](const std::filesystem::path& temporary) {
            const std::string subtitle = report.scene + ", " + std::to_string(report.size.x) + "x" +
                                         std::to_string(report.size.y) + ", " + report.device.renderer;
            const std::string program = chart.datablocks + "out = " + gnuplotString(temporary.string(), true) +
                                        "\nfamilies = " + gnuplotString(chart.families) + "\nytics = " + gnuplotString(chart.yTics) +
                                        "\nsubtitle = " + gnuplotString(subtitle) +
                                        "\nload " + gnuplotString(script, true) + "\n";
            const ProgramResult plotted = runProgram({"gnuplot"}, program);
            // Ctrl-C reaches gnuplot too (one process group): that is the interrupt, not its failure.
            throwIfInterrupted();
            if (plotted.exitCode != 0)
                throw std::runtime_error("gnuplot failed on " + script + ": " + printableMessage(plotted.output));
        });
    } else {
        text.chartNote = "The chart was not drawn: gnuplot was not found on PATH (Debian package gnuplot-nox, which "
                         "scripts/install-deps.sh installs).";
        warning = "report: " + text.chartNote;
    }
    outputs_.addText(folder_ / "index.html", reportHtml(report, text));
    outputs_.addText(folder_ / "README.md", reportMarkdown(report, text));
    outputs_.addText(folder_ / "bench.json", benchToJson(report).dump(2) + "\n");
    outputs_.addText(folder_ / "bench.csv", benchToCsv(report));
    return warning;
}

}  // namespace strata
