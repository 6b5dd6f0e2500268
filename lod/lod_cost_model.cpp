#include "lod/lod_cost_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace strata::lod {

double LodCostModel::geometryMs(double triangles, double coveredPixels, double draws) const {
    return geometryFixedMs * draws + geometryMsPerMegatriangle * triangles * 1e-6 + geometryMsPerMegapixel * coveredPixels * 1e-6;
}

double LodCostModel::impostorMs(double layerPixels) const {
    return impostorFixedMs + impostorMsPerMegapixel * layerPixels * 1e-6;
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
    const double impostor = m.impostorMs(impostorLayerPixels(sizePx, slices));
    const double geometryWithoutTriangles = m.geometryMs(0.0, area);
    if (m.geometryMsPerMegatriangle <= 0.0)
        return impostor < geometryWithoutTriangles ? 0.0 : std::numeric_limits<double>::infinity();
    return std::max(0.0, (impostor - geometryWithoutTriangles) / m.geometryMsPerMegatriangle * 1e6);
}

double crossoverSizePx(const LodCostModel& m, double triangles, int slices) {
    // impostorFixed + iP L s^2 < geometryFixed + gT T + gP s^2  <=>  (iP L - gP) s^2 < geometry(T, 0) - impostorFixed.
    const double growth = (m.impostorMsPerMegapixel * double(std::max(slices, 0)) - m.geometryMsPerMegapixel) * 1e-6;
    const double margin = m.geometryMs(triangles, 0.0) - m.impostorFixedMs;
    if (growth <= 0.0) return margin > 0.0 ? std::numeric_limits<double>::infinity() : 0.0;
    return margin > 0.0 ? std::sqrt(margin / growth) : 0.0;
}

}  // namespace strata::lod
