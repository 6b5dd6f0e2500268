#include "lod/lod_cost_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace strata::lod {

double LodCostModel::geometryMs(double triangles, double coveredPixels, double draws) const {
    return geometryFixedMs * draws + geometryMsPerMegatriangle * triangles * 1e-6 + geometryMsPerMegapixel * coveredPixels * 1e-6;
}

double LodCostModel::impostorMs(double layerPixels, double quads, double draws) const {
    const double sidePx = std::sqrt(std::max(0.0, layerPixels) * std::max(0.0, quads));
    return impostorFixedMs * draws + impostorInstanceMs + impostorMsPerKiloquad * quads * 1e-3 +
           impostorMsPerKilosidePx * sidePx * 1e-3 + impostorMsPerMegapixel * layerPixels * 1e-6;
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
    constexpr double inf = std::numeric_limits<double>::infinity();
    if (a == 0.0) return b > 0.0 ? margin / b : inf;
    // The smallest positive root of a s^2 + b s = margin; none (a < 0, the left side never
    // reaching the margin): cheaper at every size.
    const double discriminant = b * b + 4.0 * a * margin;
    if (discriminant < 0.0 || (a < 0.0 && b <= 0.0)) return inf;
    return (-b + std::sqrt(discriminant)) / (2.0 * a);
}

}  // namespace strata::lod
