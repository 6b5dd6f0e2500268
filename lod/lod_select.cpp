#include "lod/lod_select.hpp"

#include "camera/camera.hpp"
#include "lod/lod_error.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <set>
#include <stdexcept>

namespace strata::lod {

LodMode parseLodMode(std::string_view text) {
    if (text == "geometry") return LodMode::Geometry;
    if (text == "impostors") return LodMode::Impostors;
    if (text == "auto") return LodMode::Auto;
    throw std::invalid_argument("lod mode '" + std::string(text) + "' is not one of geometry|impostors|auto");
}

const char* to_string(LodMode mode) {
    switch (mode) {
    case LodMode::Geometry: return "geometry";
    case LodMode::Impostors: return "impostors";
    case LodMode::Auto: return "auto";
    }
    return "?";
}

const char* to_string(LodReason reason) {
    switch (reason) {
    case LodReason::NoTriangles: return "no triangles";
    case LodReason::EyeInside: return "eye inside";
    case LodReason::TooClose: return "too close";
    case LodReason::GeometryForced: return "geometry forced";
    case LodReason::NoImpostor: return "no impostor";
    case LodReason::ImpostorsForced: return "impostors forced";
    case LodReason::ErrorAboveBound: return "error above bound";
    case LodReason::GeometryCheaper: return "geometry cheaper";
    case LodReason::ImpostorCheaper: return "impostor cheaper";
    case LodReason::TransparentAuto: return "transparent (auto)";
    case LodReason::MaterialAuto: return "a texture the bake does not keep (auto)";
    }
    return "?";
}

LodView lodView(const Camera& camera, glm::ivec2 imageSize) {
    LodView view;
    view.eye = camera.position;
    view.fovYRadians = double(camera.fovYDegrees) * std::numbers::pi / 180.0;
    view.imageSize = imageSize;
    return view;
}

LodDecision selectLodFor(const LodObjectInput& object, const LodView& view, const LodCostModel& model,
                         const LodSelectOptions& options) {
    LodDecision d;
    const double radius = std::max(0.0, double(object.radius));
    d.distance = double(glm::length(object.center - view.eye));
    d.projectedPx = projectedDiameterPx(radius, d.distance, view.fovYRadians, view.imageSize.y);
    const double imageArea = double(std::max(view.imageSize.x, 0)) * double(std::max(view.imageSize.y, 0));
    // Screen areas clipped to the image (an infinite size, eye inside, covers the image).
    const double squarePx = std::min(d.projectedPx * d.projectedPx, imageArea);
    const double discPx = std::min(0.25 * std::numbers::pi * d.projectedPx * d.projectedPx, imageArea);
    d.geometryMs = model.geometryMs(double(object.triangles), discPx, object.drawsForGeometry());

    auto geometry = [&](LodReason why) {
        d.impostor = false;
        d.reason = why;
        return d;
    };
    if (object.triangles == 0) return geometry(LodReason::NoTriangles);
    if (d.distance <= radius) return geometry(LodReason::EyeInside);
    if (d.distance < kTooCloseRadii * radius) return geometry(LodReason::TooClose);

    if (object.hasImpostor) {
        const ImpostorSummary& s = object.impostor;
        // Level l's prediction and error into d; level 0 is the baked slices.
        auto judge = [&](int level, LodDecision& out) {
            const int slices = level == 0 ? s.slices : s.coarser[std::size_t(level - 1)].slices;
            const double fraction = level == 0 ? s.drawnFraction : s.coarser[std::size_t(level - 1)].drawnFraction;
            const double quads = level == 0 ? s.quads : s.coarser[std::size_t(level - 1)].quads;
            out.layerPixels = double(std::max(slices, 1)) * squarePx * std::clamp(fraction, 0.0, double(std::max(s.peels, 1)));
            out.quads = quads > 0.0 ? quads : double(std::max(slices, 1));
            out.impostorMs = model.impostorMs(out.layerPixels, out.quads, object.standInDraws);
            const ImpostorError e =
                impostorError(out.projectedPx, {slices, s.resolution, s.overlap, s.apexHalfAngleRadians}, s.viewAngleRadians);
            out.parallaxPx = e.parallaxPx;
            out.samplingPx = e.samplingPx;
            out.errorPx = e.totalPx();
            out.level = level;
        };
        judge(0, d);
        // Auto: the cheapest level within the bound (coarser levels trade parallax for quads),
        // adding at most the bound's raise over levelBasePx where that is set.
        const double bakedErrorPx = d.errorPx;
        const double addedAtMostPx = options.levelBasePx > 0.0 ? options.maxErrorPx - options.levelBasePx
                                                               : std::numeric_limits<double>::infinity();
        if (options.mode == LodMode::Auto && d.errorPx <= options.maxErrorPx)
            for (int level = 1; level <= std::min(s.coarserLevels, ImpostorSummary::kMaxCoarserLevels); ++level) {
                LodDecision coarse = d;
                judge(level, coarse);
                if (coarse.errorPx <= options.maxErrorPx && coarse.errorPx - bakedErrorPx <= addedAtMostPx &&
                    coarse.impostorMs < d.impostorMs)
                    d = coarse;
            }
    }
    if (options.mode == LodMode::Geometry) return geometry(LodReason::GeometryForced);
    if (!object.hasImpostor) return geometry(LodReason::NoImpostor);
    if (options.mode == LodMode::Impostors) {
        d.impostor = true;
        d.reason = LodReason::ImpostorsForced;
        return d;
    }
    if (object.transparent) return geometry(LodReason::TransparentAuto);
    if (object.materialNotBaked) return geometry(LodReason::MaterialAuto);
    if (d.errorPx > options.maxErrorPx) return geometry(LodReason::ErrorAboveBound);
    if (d.impostorMs >= d.geometryMs) return geometry(LodReason::GeometryCheaper);
    d.impostor = true;
    d.reason = LodReason::ImpostorCheaper;
    return d;
}

LodSelection selectLod(const std::vector<LodObjectInput>& objects, const LodView& view, const LodCostModel& model,
                       const LodSelectOptions& options) {
    LodSelection out;
    out.objects.reserve(objects.size());
    std::set<int> counted;
    for (const LodObjectInput& object : objects) {
        const LodDecision d = selectLodFor(object, view, model, options);
        out.geometryOnlyMs += d.geometryMs;
        out.predictedMs += d.impostor ? d.impostorMs : d.geometryMs;
        if (d.impostor) {
            out.impostorObjects += object.objects;
            // A shared impostor's memory is held once however many objects draw it.
            if (object.impostor.id < 0 || counted.insert(object.impostor.id).second) {
                ++out.impostorsUsed;
                out.impostorBytes += object.impostor.bytes;
            }
        }
        out.objects.push_back(d);
    }
    return out;
}

std::string explain(const LodDecision& d, const LodObjectInput& object, const LodSelectOptions& options) {
    char line[256];
    switch (d.reason) {
    case LodReason::NoTriangles: return "geometry: no triangles, nothing to replace";
    case LodReason::EyeInside:
        std::snprintf(line, sizeof line, "geometry: eye inside the bounds (distance %.3g <= radius %.3g)", d.distance,
                      double(object.radius));
        return line;
    case LodReason::TooClose:
        std::snprintf(line, sizeof line, "geometry: too close (distance %.3g < %.0f x radius %.3g)", d.distance,
                      kTooCloseRadii, double(object.radius));
        return line;
    case LodReason::GeometryForced: return "geometry: forced (--lod geometry)";
    case LodReason::TransparentAuto: return "geometry: transparent, impostors only with --lod impostors";
    case LodReason::MaterialAuto:
        return "geometry: a metallic-roughness, normal, occlusion or emissive texture (the impostor bakes the base "
               "colour texture, COLOR_0 and MASK only), impostors only with --lod impostors";
    case LodReason::NoImpostor: return "geometry: no impostor baked";
    case LodReason::ImpostorsForced:
        std::snprintf(line, sizeof line, "impostor: forced (--lod impostors), error %.2f px", d.errorPx);
        return line;
    case LodReason::ErrorAboveBound:
        std::snprintf(line, sizeof line, "geometry: impostor error %.2f px (parallax %.2f + sampling %.2f) > %.2f px",
                      d.errorPx, d.parallaxPx, d.samplingPx, options.maxErrorPx);
        return line;
    case LodReason::GeometryCheaper:
        std::snprintf(line, sizeof line, "geometry: cheaper, %.4f ms <= impostor %.4f ms", d.geometryMs, d.impostorMs);
        return line;
    case LodReason::ImpostorCheaper:
        std::snprintf(line, sizeof line, "impostor: cheaper, %.4f ms < geometry %.4f ms, error %.2f px <= %.2f px",
                      d.impostorMs, d.geometryMs, d.errorPx, options.maxErrorPx);
        return line;
    }
    return "?";
}

}  // namespace strata::lod
