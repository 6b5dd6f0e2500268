#include "lod/lod_cost_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace strata::lod {

double LodCostModel::geometryMs(double triangles, double coveredPixels, double draws) const {
    return geometryFixedMs * draws + geometryMsPerMegatriangle * triangles * 1e-6 + geometryMsPerMegapixel * coveredPixels * 1e-6;
}

double LodCostModel::impostorSideMs(double layerPixels, double quads) const {
    return impostorMsPerKilosidePx * std::sqrt(std::max(0.0, layerPixels) * std::max(0.0, quads)) * 1e-3;
}

double LodCostModel::impostorMs(double layerPixels, double quads, double draws) const {
    return impostorFixedMs * draws + impostorInstanceMs + impostorMsPerKiloquad * quads * 1e-3 +
           impostorSideMs(layerPixels, quads) + impostorMsPerMegapixel * layerPixels * 1e-6;
}

double predictedBakeMs(const LodCostModel& model, double triangles, int meshDraws, int resolution) {
    const double pixels = 0.5 * double(resolution) * double(resolution);
    return double(meshDraws) * model.geometryMs(triangles, pixels);
}

double impostorLayerPixels(double sizePx, int slices, double drawnFraction) {
    return double(std::max(slices, 0)) * sizePx * sizePx * std::clamp(drawnFraction, 0.0, 1.0);
}

double crossoverTriangles(const LodCostModel& m, double sizePx, int slices) {
    // geometryMs(T, s^2) = impostorMs(L s^2), solved for T.
    const double area = sizePx * sizePx;
    const double impostor = m.impostorMs(impostorLayerPixels(sizePx, slices), double(std::max(slices, 0)));
    const double geometryWithoutTriangles = m.geometryMs(0.0, area);
    if (m.geometryMsPerMegatriangle <= 0.0)
        return impostor < geometryWithoutTriangles ? 0.0 : std::numeric_limits<double>::infinity();
    return std::max(0.0, (impostor - geometryWithoutTriangles) / m.geometryMsPerMegatriangle * 1e6);
}

double crossoverSizePx(const LodCostModel& m, double triangles, int slices) {
    // impostor(0, L) + iS L s + iP L s^2 < geometryFixed + gT T + gP s^2
    //   <=>  a s^2 + b s < margin, a = iP L - gP, b = iS L (the quads' sides), margin = geometry(T, 0) - impostor(0, L).
    const double L = double(std::max(slices, 0));
    const double a = (m.impostorMsPerMegapixel * L - m.geometryMsPerMegapixel) * 1e-6;
    const double b = m.impostorMsPerKilosidePx * L * 1e-3;
    const double margin = m.geometryMs(triangles, 0.0) - m.impostorMs(0.0, L);
    if (margin <= 0.0) return 0.0;
    // The smallest positive root of a s^2 + b s = margin, written 2 margin / (b + sqrt(D)) (the
    // same root as (-b + sqrt(D)) / 2a without its cancellation when a is small, and margin / b
    // at a = 0); none (D < 0, or a denominator <= 0 when a < 0 and b <= 0): the left side never
    // reaches the margin, cheaper at every size.
    const double discriminant = b * b + 4.0 * a * margin;
    if (discriminant < 0.0) return std::numeric_limits<double>::infinity();
    const double denominator = b + std::sqrt(discriminant);
    return denominator > 0.0 ? 2.0 * margin / denominator : std::numeric_limits<double>::infinity();
}

}  // namespace strata::lod
