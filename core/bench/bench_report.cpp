// The bench report in the three shapes it is read in: the JSON contract of DESIGN.md, a
// table for people, and CSV for plots.
#include "bench/bench.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <sstream>

namespace strata {
namespace {

// JSON has no NaN or infinity; the contract promises finite numbers.
double finite(double v) { return std::isfinite(v) ? v : 0.0; }

std::string fmt(const char* format, double v) { return formatNumber(format, v); }

}  // namespace

std::string formatNumber(const char* format, double value) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, format, value);
    return buffer;
}

std::string humanBytes(std::uint64_t bytes) {
    if (bytes >= (1ull << 20)) return fmt("%.1f MiB", double(bytes) / double(1 << 20));
    if (bytes >= 1024) return fmt("%.1f KiB", double(bytes) / 1024.0);
    return std::to_string(bytes) + " B";
}

std::optional<double> floorMs(const BenchReport& r) {
    for (const auto& m : r.modes)
        if (m.id == "floor" && m.msMedian > 0.0) return m.msMedian;
    return std::nullopt;
}

nlohmann::json benchToJson(const BenchReport& r) {
    nlohmann::json modes = nlohmann::json::array();
    const std::optional<double> floorTime = floorMs(r);
    for (const auto& m : r.modes) {
        nlohmann::json passes = nlohmann::json::object();
        for (const auto& [name, ms] : m.passMsMedian) passes[name] = finite(ms);
        modes.push_back({
            {"id", m.id}, {"family", m.family}, {"reference", m.reference}, {"robust", m.robust}, {"handles_coplanarity", m.handlesCoplanarity},
            {"rgb_transmittance", m.rgbTransmittance},
            {"ms_median", finite(m.msMedian)}, {"ms_p95", finite(m.msP95)}, {"cpu_ms_median", finite(m.cpuMsMedian)},
            {"wall_ms_median", m.wallMsMedian >= 0.0 ? nlohmann::json(m.wallMsMedian) : nlohmann::json(nullptr)},
            {"thread_cpu_ms_median", finite(m.threadCpuMsMedian)}, {"draw_calls_median", finite(m.drawCallsMedian)},
            {"lod_ms_median", finite(m.lodMsMedian)},
            {"opaque_ms_median", finite(m.opaqueMsMedian)}, {"pass_ms_median", passes},
            {"passes", m.passes}, {"bytes", m.bytes},
            {"fragments_total", m.fragmentsTotal}, {"fragments_captured", m.fragmentsCaptured},
            {"robustness_ratio", finite(m.robustnessRatio)}, {"overflowed", m.overflowed},
            {"regrows", m.regrows}, {"tiles", m.tiles}, {"object_draws", m.objectDraws},
            {"object_draws_skipped", m.objectDrawsSkipped}, {"objects_culled", m.objectsCulled}, {"units_culled", m.unitsCulled}, {"fragments_tail", m.fragmentsTail},
            {"fragments_dropped", m.fragmentsDropped}, {"primitives_bounded", m.primitivesBounded},
            {"rmse", finite(m.rmse)}, {"psnr", finite(m.psnr)}, {"max_abs_error", finite(m.maxAbsError)},
        });
        if (floorTime) modes.back()["ms_over_floor"] = finite(m.msMedian / *floorTime);
        // What the row was measured with: the cost and loss of a setting are read off two rows.
        nlohmann::json settings = nlohmann::json::object();
        for (std::size_t i = 0; i < m.settingDescriptions.size() && i < m.settings.size(); ++i) {
            const auto& d = m.settingDescriptions[i];
            if (d.type == SettingType::Flag) settings[d.name] = m.settings[i] != 0;
            else if (d.type == SettingType::Integer) settings[d.name] = std::int64_t(m.settings[i]);
            else settings[d.name] = m.settings[i];
        }
        modes.back()["settings"] = settings;
        modes.back()["frame_ms_median"] = finite(m.frameMsMedian);
        modes.back()["frame_span_ms_median"] = finite(m.frameSpanMsMedian);
        modes.back()["enlarge_ms_median"] = finite(m.enlargeMsMedian);
        modes.back()["zoom"] = m.zoom;
        modes.back()["impostor_objects"] = m.impostorObjects;
        modes.back()["impostor_bytes"] = m.impostorBytes;
        if (r.budget) {
            nlohmann::json excursions = nlohmann::json::array();
            for (const auto& e : m.excursions)
                excursions.push_back({{"first_frame", e.firstFrame}, {"frames", e.frames},
                                      {"peak_over_target", finite(e.peakOverTarget)}});
            nlohmann::json predicted = nlohmann::json::array();
            for (double p : m.framePredictedMs) predicted.push_back(finite(p));
            nlohmann::json times = nlohmann::json::array();
            for (double t : m.frameMs) times.push_back(finite(t));
            nlohmann::json psnr = nlohmann::json::array();
            for (double p : m.framePsnr) psnr.push_back(finite(p));
            nlohmann::json bounds = nlohmann::json::array(), losses = nlohmann::json::array();
            for (double b : m.frameLodBoundPx) bounds.push_back(finite(b));
            for (double l : m.frameLossPx) losses.push_back(finite(l));
            modes.back()["budget"] = {
                {"frame_zoom", m.frameZoom}, {"frame_ms", times}, {"frame_predicted_ms", predicted},
                {"frame_impostor_objects", m.frameImpostorObjects}, {"frame_psnr", psnr},
                {"frame_lod_bound_px", bounds}, {"frame_loss_px", losses},
                {"within_band", finite(m.budgetHits.within)}, {"not_over_band", finite(m.budgetHits.notOver)},
                {"excursions", excursions},
                {"model", {{"fixed_ms", finite(m.calibratedModel.fixedMs)},
                           {"ms_per_megapixel", finite(m.calibratedModel.msPerMegapixel)},
                           {"ms_per_megafragment", finite(m.calibratedModel.msPerMegafragment)}}},
            };
        }
    }
    return {
        {"scene", r.scene},
        {"size", {r.size.x, r.size.y}},
        {"frames", r.frames},
        {"device", {{"vendor", r.device.vendor}, {"renderer", r.device.renderer}, {"version", r.device.version}}},
        {"reference", r.reference},
        {"modes", modes},
        {"coplanarity_probability", finite(r.coplanarityProbability)},
        {"coplanarity_one_per_layer_robustness", finite(r.coplanarityOnePerLayerRobustness)},
        {"coplanarity_pixels_by_largest_layer", r.pixelsByLargestLayer},
        {"triangles", r.triangles},
        {"texture_bytes", r.textureBytes},
        {"objects", r.objects},
        {"meshes", r.meshes},
        {"mesh_triangles", r.meshTriangles},
        {"mesh_bytes", r.meshBytes},
        {"zoom", r.zoom},
        {"zoom_filter", r.zoomFilter},
        {"reference_supersample", r.referenceSupersample},
        {"frame_budget_ms", r.budget ? finite(r.budget->targetMs) : 0.0},
        {"zoom_controller", r.zoomController},
        {"budget_levers", r.budgetLevers},
        {"budget_pin", r.budgetPin ? nlohmann::json{{"zoom", r.budgetPin->zoom}, {"lod_level", r.budgetPin->lodLevel}}
                                   : nlohmann::json()},
        {"lod", r.lod},
        {"interrupted", r.interrupted},
    };
}

std::string benchToTable(const BenchReport& r) {
    std::ostringstream out;
    out << "scene " << r.scene << "  " << r.size.x << "x" << r.size.y << "  " << r.frames << " frames  "
        << r.objects << " objects, " << r.triangles << " triangles (" << r.meshes << " distinct meshes, "
        << r.meshTriangles << " triangles, " << fmt("%.1f", double(r.meshBytes) / (1024.0 * 1024.0)) << " MiB)\n";
    out << "device " << r.device.renderer << " (" << r.device.vendor << ", " << r.device.version << ")\n";
    out << "coplanarity probability C_p " << fmt("%.3f", r.coplanarityProbability) << "  R_h one per layer "
        << fmt("%.3f", r.coplanarityOnePerLayerRobustness) << "  reference " << r.reference;
    // Rows measured against another reference (the volumetric family's) are named, so no error
    // figure reads as measured against the header's reference when it was not.
    std::map<std::string, std::string> otherReferences;
    for (const auto& m : r.modes)
        if (m.reference != r.reference && m.reference != m.id) otherReferences[m.reference] += (otherReferences[m.reference].empty() ? "" : ", ") + m.id;
    for (const auto& [reference, rows] : otherReferences) out << " (" << reference << " for " << rows << ")";
    out << "\n";
    if (r.budget && r.budgetPin)
        out << "every frame pinned at zoom " << r.budgetPin->zoom << ", LOD ladder level " << r.budgetPin->lodLevel << " ("
            << fmt("%.2f", r.budget->targetMs) << " ms budget); errors against the reference at zoom 1\n";
    else if (r.budget)
        out << "zoom chosen per frame by the " << r.zoomController << " controller for " << fmt("%.2f", r.budget->targetMs)
            << " ms (+-" << fmt("%.0f", r.budget->band * 100.0) << " %), zoom " << r.budget->minZoom << ".."
            << r.budget->maxZoom << ", " << r.zoomFilter << "; errors against the reference at zoom 1\n";
    else if (r.zoom > 1)
        out << "zoom " << r.zoom << " (" << r.zoomFilter << "): drawn at 1/" << r.zoom
            << " size and enlarged; errors against the reference at zoom 1\n";
    if (r.interrupted)
        out << "INTERRUPTED: " << r.modes.size() << " of " << r.modesPlanned
            << " techniques completed before the signal; only they are listed\n";
    out << "\n";
    const std::optional<double> floorTime = floorMs(r);
    char line[256];
    std::snprintf(line, sizeof line, "%-16s %9s %9s %9s %6s %11s %12s %7s %9s %8s %9s%s\n", "mode", "gpu ms", "p95 ms",
                  "cpu ms", "passes", "memory", "fragments", "ratio", "rmse", "psnr", "max err", floorTime ? "   x floor" : "");
    out << line;
    for (const auto& m : r.modes) {
        std::string overFloor = floorTime ? fmt(" %9.2f", m.msMedian / *floorTime) : "";
        std::snprintf(line, sizeof line, "%-16s %9.3f %9.3f %9.2f %6d %11s %12llu %7.4f %9.2e %8.2f %9.2e%s%s\n",
                      m.id.c_str(), m.msMedian, m.msP95, m.cpuMsMedian, m.passes, humanBytes(m.bytes).c_str(),
                      (unsigned long long)m.fragmentsCaptured, m.robustnessRatio, m.rmse, m.psnr, m.maxAbsError,
                      overFloor.c_str(), m.overflowed ? "  OVERFLOW" : (m.regrows ? "  (grew)" : ""));
        out << line;
    }
    if (std::any_of(r.modes.begin(), r.modes.end(), [](const BenchMode& m) { return m.wallMsMedian >= 0.0; })) {
        // --wall: the same frames untimed, as the peers time theirs; the whole frame (opaque pass
        // included) to a glFinish.
        out << "\nwall clock, the same frames without pass timers or fragment count (as the peers time theirs):\n";
        std::snprintf(line, sizeof line, "%-16s %9s %9s\n", "mode", "wall ms", "cpu ms");
        out << line;
        for (const auto& m : r.modes) {
            if (m.wallMsMedian < 0.0) continue;
            std::snprintf(line, sizeof line, "%-16s %9.2f %9.2f\n", m.id.c_str(), m.wallMsMedian, m.cpuMsMedian);
            out << line;
        }
    }
    if (r.zoom > 1 || r.budget) {
        out << "\n";
        std::snprintf(line, sizeof line, "%-16s %9s %10s %9s %9s %9s %s\n", "mode", "frame ms", "enlarge ms", "mean z",
                      "in band", "<= band", "excursions over the band (first frame: frames, peak/target)");
        out << line;
        for (const auto& m : r.modes) {
            double meanZoom = m.zoom;
            if (!m.frameZoom.empty()) {
                meanZoom = 0.0;
                for (int z : m.frameZoom) meanZoom += z;
                meanZoom /= double(m.frameZoom.size());
            }
            std::string runs;
            for (const auto& e : m.excursions)
                runs += " " + std::to_string(e.firstFrame) + ":" + std::to_string(e.frames) + fmt(",%.2f", e.peakOverTarget);
            std::snprintf(line, sizeof line, "%-16s %9.3f %10.3f %9.2f %9s %9s%s\n", m.id.c_str(), m.frameMsMedian,
                          m.enlargeMsMedian, meanZoom, r.budget ? fmt("%.2f", m.budgetHits.within).c_str() : "-",
                          r.budget ? fmt("%.2f", m.budgetHits.notOver).c_str() : "-", runs.c_str());
            out << line;
        }
    }
    // The floor is the least work any technique can do on these fragments: a row below it
    // means noise (llvmpipe shares the CPU) or a floor that is not one.
    if (floorTime)
        for (const auto& m : r.modes)
            if (m.id != "floor" && m.msMedian < 0.95 * *floorTime)
                out << "note: " << m.id << " measured " << fmt("%.2f", m.msMedian / *floorTime)
                    << "x the floor (below 0.95): noise, or the floor is not a lower bound\n";
    return out.str();
}

std::string benchToCsv(const BenchReport& r) {
    std::ostringstream out;
    out << "scene,width,height,frames,mode,family,robust,handles_coplanarity,ms_median,ms_p95,cpu_ms_median,"
           "passes,bytes,fragments_total,fragments_captured,robustness_ratio,overflowed,rmse,psnr,max_abs_error";
    // The floor's column is last, so the columns before it keep their positions with or without
    // a floor row.
    const std::optional<double> floorTime = floorMs(r);
    out << ",reference" << (floorTime ? ",ms_over_floor\n" : "\n");
    for (const auto& m : r.modes) {
        out << r.scene << ',' << r.size.x << ',' << r.size.y << ',' << r.frames << ',' << m.id << ',' << m.family
            << ',' << m.robust << ',' << m.handlesCoplanarity << ',' << finite(m.msMedian) << ',' << finite(m.msP95)
            << ',' << finite(m.cpuMsMedian) << ',' << m.passes << ',' << m.bytes << ',' << m.fragmentsTotal << ','
            << m.fragmentsCaptured << ',' << finite(m.robustnessRatio) << ',' << m.overflowed << ','
            << finite(m.rmse) << ',' << finite(m.psnr) << ',' << finite(m.maxAbsError);
        out << ',' << m.reference;
        if (floorTime) out << ',' << finite(m.msMedian / *floorTime);
        out << '\n';
    }
    return out.str();
}

}  // namespace strata
