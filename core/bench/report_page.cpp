#include "bench/report_page.hpp"

#include "image/image.hpp"
#include "render/coplanarity.hpp"
#include "render/error_map.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <sstream>

namespace strata {
namespace {

std::string fmt(const char* format, double v) { return formatNumber(format, v); }

// A linear RGB colour as CSS "#rrggbb" (sRGB-encoded, as the PNGs are).
std::string cssColor(const glm::vec3& linear) {
    char buffer[8];
    auto byte = [](float v) { return int(std::lround(std::clamp(linearToSrgb(v), 0.0f, 1.0f) * 255.0f)); };
    std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x", byte(linear.r), byte(linear.g), byte(linear.b));
    return buffer;
}

// Every fragment kept, nothing overflowed, no channel off by more than an 8-bit step.
bool exactRow(const BenchMode& m) {
    return !m.overflowed && m.fragmentsDropped == 0 && m.fragmentsCaptured >= m.fragmentsTotal &&
           m.maxAbsError <= 1.0 / 255.0;
}

// Rows that compete on the report's own reference: not the floor, not a volumetric row.
bool comparable(const BenchReport& r, const BenchMode& m) { return m.reference == r.reference && m.id != "floor"; }

std::vector<std::string> familiesOf(const BenchReport& r) {
    std::vector<std::string> families;
    for (const auto& m : r.modes)
        if (std::find(families.begin(), families.end(), m.family) == families.end()) families.push_back(m.family);
    return families;
}

std::string psnrText(double psnr) { return psnr >= 100.0 ? "identical" : fmt("%.1f dB", psnr); }

// One cell of the sortable table: shown text, and the value it sorts by.
std::string numberCell(const std::string& shown, double value) {
    return "<td data-v=\"" + fmt("%.9g", value) + "\">" + shown + "</td>";
}

const char* kStyle = R"(
body { font: 15px/1.45 system-ui, sans-serif; margin: 0 auto; max-width: 1320px; padding: 0 16px 40px; color: #1b1b1b; }
h1 { margin: 20px 0 4px; font-size: 26px; } h2 { margin-top: 32px; border-bottom: 1px solid #ddd; }
.meta { color: #555; margin: 0; } code { background: #f3f3f3; padding: 0 3px; }
.pair { display: flex; flex-wrap: wrap; gap: 12px; } .pair figure { margin: 0; flex: 1 1 300px; }
img { max-width: 100%; height: auto; display: block; } figcaption { font-size: 13px; color: #444; }
.legend { border-collapse: collapse; font-size: 13px; } .legend td { padding: 1px 8px 1px 0; }
.legend td.swatch { width: 14px; padding: 0; border: 1px solid #888; }
.ramp { height: 12px; max-width: 420px; border: 1px solid #888; }
.sheet { display: grid; grid-template-columns: repeat(auto-fill, minmax(min(100%, 430px), 1fr)); gap: 14px; }
.card { margin: 0; border: 1px solid #ddd; border-radius: 4px; padding: 6px; }
.card .thumbs { display: grid; grid-template-columns: 1fr 1fr; gap: 4px; }
.card.over { border-color: #d62728; } .bad { color: #b00; font-weight: 600; }
.tablewrap { overflow-x: auto; } table.results { border-collapse: collapse; font-size: 13px; }
.results th, .results td { padding: 2px 8px; text-align: right; white-space: nowrap; border-bottom: 1px solid #eee; }
.results th:nth-child(-n+3), .results td:nth-child(-n+3) { text-align: left; }
.results th button { font: inherit; font-weight: 600; border: 0; background: none; cursor: pointer; padding: 0; }
#broken { background: #fee; border: 1px solid #d62728; padding: 6px; }
)";

// Sorts the table by a clicked column (numbers by data-v, text otherwise; again reverses), and
// says when an image of the folder did not load. Nothing else runs; the page reads without it.
const char* kScript = R"(
document.querySelectorAll('table.results th button').forEach(function (button, column) {
  button.addEventListener('click', function () {
    var body = button.closest('table').tBodies[0];
    var up = button.dataset.order !== 'up';
    button.dataset.order = up ? 'up' : 'down';
    var key = function (row) { var c = row.cells[column]; return c.dataset.v !== undefined ? parseFloat(c.dataset.v) : c.textContent; };
    Array.from(body.rows).sort(function (a, b) {
      var x = key(a), y = key(b);
      var order = typeof x === 'number' ? x - y : String(x).localeCompare(String(y));
      return up ? order : -order;
    }).forEach(function (row) { body.appendChild(row); });
  });
});
window.addEventListener('load', function () {
  var broken = Array.from(document.images).filter(function (i) { return !i.complete || i.naturalWidth === 0; });
  document.body.dataset.brokenImages = String(broken.length);
  if (broken.length) {
    var note = document.getElementById('broken');
    note.textContent = broken.length + ' image(s) of this report did not load (is the folder complete?): ' +
        broken.map(function (i) { return i.getAttribute('src'); }).join(', ');
    note.hidden = false;
  }
});
)";

std::string img(const std::string& src, glm::ivec2 size, const std::string& alt) {
    return "<img src=\"" + htmlEscape(src) + "\" width=\"" + std::to_string(size.x) + "\" height=\"" +
           std::to_string(size.y) + "\" alt=\"" + htmlEscape(alt) + "\">";
}

void writeHeatmapLegend(std::ostringstream& out, const BenchReport& r) {
    std::uint64_t withFragments = 0;
    for (int k = 1; k < kCoplanarityBins; ++k) withFragments += r.pixelsByLargestLayer[std::size_t(k)];
    out << "<table class=\"legend\"><tbody>\n";
    for (int k = 1; k < kCoplanarityBins; ++k) {
        const std::uint64_t n = r.pixelsByLargestLayer[std::size_t(k)];
        out << "<tr><td class=\"swatch\" style=\"background:" << cssColor(coplanarityColor(k)) << "\"></td><td>"
            << coplanarityColorName(k) << "</td><td>" << (k == 1 ? "one fragment per layer" : std::to_string(k) + (k == kCoplanarityBins - 1 ? " or more" : "") + " in one layer")
            << "</td><td>" << n << " px</td><td>" << fmt("%.1f %%", withFragments ? 100.0 * double(n) / double(withFragments) : 0.0)
            << "</td></tr>\n";
    }
    out << "</tbody></table>\n";
}

void writeCard(std::ostringstream& out, const BenchMode& m, const ReportPageText& text,
               const std::optional<double>& floorTime) {
    const std::string id = htmlEscape(m.id);
    out << "<figure class=\"card" << (m.overflowed ? " over" : "") << "\" id=\"m-" << id << "\">\n<div class=\"thumbs\">"
        << "<a href=\"images/" << id << ".png\">" << img("thumbs/" + m.id + ".png", text.thumbnailSize, m.id + ": image") << "</a>"
        << "<a href=\"errors/" << id << ".png\">" << img("thumbs/" + m.id + "-error.png", text.thumbnailSize, m.id + ": error map")
        << "</a></div>\n<figcaption><b>" << id << "</b> " << fmt("%.2f ms", m.msMedian);
    if (floorTime) out << fmt(" &middot; %.2f&times; floor", m.msMedian / *floorTime);
    out << " &middot; " << psnrText(m.psnr) << " &middot; " << m.passes << (m.passes == 1 ? " pass" : " passes") << " &middot; "
        << htmlEscape(humanBytes(m.bytes));
    if (m.overflowed) out << " &middot; <span class=\"bad\">overflowed</span>";
    if (m.fragmentsDropped) out << " &middot; <span class=\"bad\">" << m.fragmentsDropped << " fragments not kept</span>";
    out << "<br>error against <code>" << htmlEscape(m.reference) << "</code>" << (m.reference == m.id ? " (itself: the reference)" : "")
        << (exactRow(m) ? ", exact" : fmt(", max %.3f", m.maxAbsError)) << "</figcaption>\n</figure>\n";
}

void writeTable(std::ostringstream& out, const BenchReport& r, const std::optional<double>& floorTime) {
    const char* headers[] = {"mode", "family", "reference", "gpu ms", "p95 ms", "cpu ms", "x floor", "passes",
                             "memory", "fragments", "ratio", "rmse", "psnr", "max err"};
    out << "<div class=\"tablewrap\"><table class=\"results\"><thead><tr>";
    for (const char* h : headers)
        if (floorTime || std::string(h) != "x floor") out << "<th><button type=\"button\">" << h << "</button></th>";
    out << "</tr></thead>\n<tbody>\n";
    for (const auto& m : r.modes) {
        out << "<tr><td><a href=\"#m-" << htmlEscape(m.id) << "\">" << htmlEscape(m.id) << "</a>"
            << (m.overflowed ? " <span class=\"bad\">overflow</span>" : "") << "</td><td>" << htmlEscape(m.family)
            << "</td><td>" << htmlEscape(m.reference) << "</td>" << numberCell(fmt("%.3f", m.msMedian), m.msMedian)
            << numberCell(fmt("%.3f", m.msP95), m.msP95) << numberCell(fmt("%.2f", m.cpuMsMedian), m.cpuMsMedian);
        if (floorTime) out << numberCell(fmt("%.2f", m.msMedian / *floorTime), m.msMedian / *floorTime);
        out << numberCell(std::to_string(m.passes), m.passes) << numberCell(htmlEscape(humanBytes(m.bytes)), double(m.bytes))
            << numberCell(std::to_string(m.fragmentsCaptured), double(m.fragmentsCaptured))
            << numberCell(fmt("%.4f", m.robustnessRatio), m.robustnessRatio) << numberCell(fmt("%.2e", m.rmse), m.rmse)
            << numberCell(fmt("%.2f", m.psnr), m.psnr) << numberCell(fmt("%.2e", m.maxAbsError), m.maxAbsError) << "</tr>\n";
    }
    out << "</tbody></table></div>\n";
}

std::string frontSentence(const BenchReport& r) {
    std::string s;
    for (std::size_t i : paretoFront(r)) {
        const BenchMode& m = r.modes[i];
        s += (s.empty() ? "" : ", ") + m.id + " (" + fmt("%.2f ms", m.msMedian) + ", " +
             (m.rmse > 0.0 ? fmt("RMSE %.1e", m.rmse) : std::string("exact")) + ")";
    }
    return s;
}

}  // namespace

std::string htmlEscape(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        case '\'': out += "&#39;"; break;
        default: out += c;
        }
    }
    return out;
}

std::vector<std::size_t> paretoFront(const BenchReport& r) {
    std::vector<std::size_t> candidates;
    for (std::size_t i = 0; i < r.modes.size(); ++i)
        if (comparable(r, r.modes[i])) candidates.push_back(i);
    std::vector<std::size_t> front;
    for (std::size_t i : candidates) {
        const BenchMode& a = r.modes[i];
        const bool dominated = std::any_of(candidates.begin(), candidates.end(), [&](std::size_t j) {
            const BenchMode& b = r.modes[j];
            return j != i && b.msMedian <= a.msMedian && b.rmse <= a.rmse && (b.msMedian < a.msMedian || b.rmse < a.rmse);
        });
        if (!dominated) front.push_back(i);
    }
    std::sort(front.begin(), front.end(), [&](std::size_t a, std::size_t b) { return r.modes[a].msMedian < r.modes[b].msMedian; });
    return front;
}

std::vector<std::string> reportVerdict(const BenchReport& r) {
    std::vector<std::string> lines;
    const std::optional<double> floorTime = floorMs(r);
    auto overFloor = [&](const BenchMode& m) { return floorTime ? fmt(" (%.2fx the floor)", m.msMedian / *floorTime) : std::string(); };
    const BenchMode* fastestExact = nullptr;
    for (const auto& m : r.modes)
        if (comparable(r, m) && exactRow(m) && (!fastestExact || m.msMedian < fastestExact->msMedian)) fastestExact = &m;
    if (fastestExact)
        lines.push_back("Fastest exact technique: " + fastestExact->id + ", " + fmt("%.2f ms", fastestExact->msMedian) +
                        overFloor(*fastestExact) + ".");
    else
        lines.push_back("No technique measured here is exact (every fragment kept, no channel off by more than 1/255).");
    if (floorTime) {
        const BenchMode* best = nullptr;
        for (const auto& m : r.modes)
            if (comparable(r, m) && m.msMedian <= 2.0 * *floorTime && (!best || m.rmse < best->rmse)) best = &m;
        if (best)
            lines.push_back("Most accurate within 2x the floor (" + fmt("%.2f ms", 2.0 * *floorTime) + "): " + best->id + ", " +
                            psnrText(best->psnr) + " at " + fmt("%.2f ms", best->msMedian) + overFloor(*best) + ".");
        else
            lines.push_back("No technique ran within 2x the floor (" + fmt("%.2f ms", 2.0 * *floorTime) + ").");
    } else {
        lines.push_back("The floor was not measured (add it to --modes), so no technique is placed against it.");
    }
    // Overflow (storage ran out) and fragments counted but not kept (a peeling's coplanar ties,
    // sampling that stored fewer than it drew) are named apart: they have different causes.
    std::string overflowed, lost;
    for (const auto& m : r.modes) {
        const std::string kept = m.id + " kept " + std::to_string(m.fragmentsCaptured) + " of " + std::to_string(m.fragmentsTotal);
        if (m.overflowed) overflowed += (overflowed.empty() ? "" : "; ") + kept;
        else if (m.fragmentsDropped) lost += (lost.empty() ? "" : "; ") + kept;
    }
    lines.push_back(overflowed.empty() ? "Nothing overflowed." : "Overflowed: " + overflowed + " fragments.");
    if (!lost.empty()) lines.push_back("Fragments counted and not kept: " + lost + ".");
    return lines;
}

TradeoffChartData tradeoffChartData(const BenchReport& r) {
    TradeoffChartData chart;
    const std::vector<std::string> families = familiesOf(r);
    for (const auto& f : families) chart.families += (chart.families.empty() ? "" : " ") + f;
    double smallest = std::numeric_limits<double>::infinity(), largest = 0.0;
    for (const auto& m : r.modes)
        if (m.rmse > 0.0) smallest = std::min(smallest, m.rmse), largest = std::max(largest, m.rmse);
    // Exact rows sit one decade below the lowest decade any other row reaches, labelled "exact";
    // the axis is labelled every decade above it.
    const int lowDecade = std::isfinite(smallest) ? std::min(-6, int(std::floor(std::log10(smallest)))) : -6;
    const int highDecade = largest > 0.0 ? std::max(lowDecade + 1, int(std::ceil(std::log10(largest)))) : lowDecade + 1;
    chart.exactRmse = std::pow(10.0, lowDecade - 1);
    chart.yTics = "\"exact\" " + fmt("%.0e", chart.exactRmse);
    const int step = highDecade - lowDecade > 8 ? 2 : 1;  // at most ~8 labels
    for (int d = highDecade; d >= lowDecade; d -= step) chart.yTics += ", \"1e" + std::to_string(d) + "\" 1e" + std::to_string(d);
    // Log axes need positive values: a zero time (a row that drew nothing) sits at a microsecond.
    auto x = [](double ms) { return fmt("%.9g", std::max(ms, 1e-3)); };
    auto y = [&](double rmse) { return fmt("%.9g", rmse > 0.0 ? rmse : chart.exactRmse); };
    std::ostringstream out;
    out << "$points << EOD\n";
    for (const auto& m : r.modes) {
        const auto family = std::find(families.begin(), families.end(), m.family) - families.begin();
        out << x(m.msMedian) << ' ' << y(m.rmse) << ' ' << family << " \"" << m.id << "\" " << (m.reference != r.reference) << '\n';
    }
    out << "EOD\n$front << EOD\n";
    for (std::size_t i : paretoFront(r)) out << x(r.modes[i].msMedian) << ' ' << y(r.modes[i].rmse) << " \"" << r.modes[i].id << "\"\n";
    out << "EOD\n";
    chart.datablocks = out.str();
    return chart;
}

std::string reportHtml(const BenchReport& r, const ReportPageText& text) {
    const std::optional<double> floorTime = floorMs(r);
    std::ostringstream out;
    out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
        << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>" << htmlEscape(text.title)
        << " &mdash; " << htmlEscape(r.scene) << "</title>\n<style>" << kStyle << "</style>\n</head>\n<body>\n";
    out << "<h1>" << htmlEscape(text.title) << "</h1>\n<p class=\"meta\">Scene <code>" << htmlEscape(r.scene) << "</code>, "
        << r.size.x << "&times;" << r.size.y << ", " << r.frames << (r.frames == 1 ? " frame" : " frames") << " per technique, "
        << r.objects << " objects, " << r.triangles << " triangles</p>\n<p class=\"meta\">Device " << htmlEscape(r.device.renderer)
        << " (" << htmlEscape(r.device.vendor) << ", " << htmlEscape(r.device.version) << "), " << htmlEscape(text.date) << "</p>\n";
    if (!text.command.empty()) out << "<p class=\"meta\">Made by <code>" << htmlEscape(text.command) << "</code></p>\n";
    if (r.interrupted)
        out << "<p class=\"bad\">Interrupted: " << r.modes.size() << " of " << r.modesPlanned
            << " techniques completed before the signal; only they are shown.</p>\n";
    out << "<p id=\"broken\" hidden></p>\n";

    out << "<h2>The scene</h2>\n";
    if (!text.description.empty()) out << "<p>" << htmlEscape(text.description) << "</p>\n";
    const std::string exact = text.exactReference.empty() ? r.reference : text.exactReference;
    out << "<div class=\"pair\">\n<figure>" << img("exact.png", text.imageSize, "the exact image (" + exact + ")")
        << "<figcaption>The exact image: <code>" << htmlEscape(exact) << "</code>, the reference the rows' errors are "
        << "measured against (each row names its own).</figcaption></figure>\n<figure>" << img("heatmap.png", text.imageSize, "coplanarity heatmap")
        << "<figcaption>Coplanarity heatmap (Vasilakis and Fudos, Fig. 13): per pixel the most fragments that share one "
        << "depth layer. C<sub>p</sub> = " << fmt("%.3f", r.coplanarityProbability) << " of the pixels with fragments have "
        << "coplanar ones; a technique that keeps one fragment per layer (f2b, dual, bun) keeps R<sub>h</sub> = "
        << fmt("%.3f", r.coplanarityOnePerLayerRobustness) << " of them.</figcaption>\n";
    writeHeatmapLegend(out, r);
    out << "</figure>\n</div>\n";

    out << "<h2>Verdict</h2>\n<ul>\n";
    for (const auto& line : reportVerdict(r)) out << "<li>" << htmlEscape(line) << "</li>\n";
    out << "</ul>\n";

    out << "<h2>Speed against accuracy</h2>\n";
    if (text.chartNote.empty())
        out << "<figure><img src=\"chart.svg\" width=\"960\" height=\"600\" alt=\"GPU ms against RMSE, every technique\">";
    else
        out << "<figure><p class=\"bad\">" << htmlEscape(text.chartNote) << "</p>";
    out << "<figcaption>Every technique's median GPU time against its RMSE (log-log, coloured by family; exact rows at the "
        << "bottom; open circles are measured against another reference). The Pareto front, where nothing is both faster "
        << "and more accurate: " << htmlEscape(frontSentence(r)) << ".</figcaption></figure>\n";

    out << "<h2>Contact sheet</h2>\n<p>Each technique's first frame and its error map against its reference (click for "
        << "the full size). Error map: where nothing differs, the scene dimmed to grey; elsewhere the largest channel "
        << "difference, from dark blue to red at " << fmt("%.2f", kReportErrorScale) << " (linear) and above, the same "
        << "scale for every technique:</p>\n<div class=\"ramp\" style=\"background: linear-gradient(to right";
    for (int i = 0; i <= 10; ++i) out << ", " << cssColor(errorMapRamp(float(i) / 10.0f));
    out << ")\"></div>\n";
    for (const auto& family : familiesOf(r)) {
        out << "<h3>" << htmlEscape(family) << "</h3>\n<div class=\"sheet\">\n";
        for (const auto& m : r.modes)
            if (m.family == family) writeCard(out, m, text, floorTime);
        out << "</div>\n";
    }

    out << "<h2>All figures</h2>\n<p>Click a column to sort by it. The same figures as <a href=\"bench.json\">bench.json</a> "
        << "and <a href=\"bench.csv\">bench.csv</a>; <a href=\"README.md\">README.md</a> is the summary in Markdown.</p>\n";
    writeTable(out, r, floorTime);
    out << "<script>" << kScript << "</script>\n</body>\n</html>\n";
    return out.str();
}

std::string reportMarkdown(const BenchReport& r, const ReportPageText& text) {
    std::ostringstream out;
    out << "# " << text.title << "\n\n";
    if (!text.description.empty()) out << text.description << "\n\n";
    out << "Device " << r.device.renderer << ", " << text.date << ". Open `index.html` for the chart, the contact sheet of "
        << "every technique's image and error map, and a sortable table.\n\n";
    out << "| exact image (`" << (text.exactReference.empty() ? r.reference : text.exactReference) << "`) | coplanarity heatmap (C_p " << fmt("%.3f", r.coplanarityProbability)
        << ") |\n|---|---|\n| ![exact](exact.png) | ![heatmap](heatmap.png) |\n\n";
    if (text.chartNote.empty()) out << "![speed against accuracy](chart.svg)\n\n";
    for (const auto& line : reportVerdict(r)) out << "- " << line << "\n";
    out << "- Pareto front: " << frontSentence(r) << ".\n\n```\n" << benchToTable(r) << "```\n";
    return out.str();
}

}  // namespace strata
