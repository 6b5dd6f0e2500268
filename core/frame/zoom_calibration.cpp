#include "frame/zoom_calibration.hpp"

#include "render/frustum.hpp"

#include "frame/frame_renderer.hpp"
#include "gl/debug.hpp"
#include "scene/builtin_scenes.hpp"

#include <algorithm>
#include <cmath>

namespace strata {
namespace {

// Least squares for t = c0 + c1 x1 + c2 x2 through the normal equations (3x3, double).
glm::dvec3 fitPlane(const std::vector<ZoomCalibrationPoint>& points, bool withPixels, bool withFragments) {
    glm::dmat3 a(0.0);
    glm::dvec3 b(0.0);
    for (const auto& p : points) {
        const glm::dvec3 x(1.0, withPixels ? p.pixels * 1e-6 : 0.0, withFragments ? p.fragments * 1e-6 : 0.0);
        a += glm::outerProduct(x, x);
        b += x * p.ms;
    }
    // A term left out gets a unit diagonal so the system stays solvable and its slope is 0.
    if (!withPixels) a[1][1] = 1.0;
    if (!withFragments) a[2][2] = 1.0;
    return glm::inverse(a) * b;
}

}  // namespace

std::uint64_t fragmentsRasterized(const TechniqueStats& stats) {
    return stats.fragmentsCaptured + stats.fragmentsDropped + stats.fragmentsTail;
}

double transparentScreenArea(const GpuScene& scene, const glm::mat4& viewProjection, glm::ivec2 displaySize) {
    const double full = double(displaySize.x) * double(displaySize.y);
    double area = 0.0;
    // What the frame culls draws nothing (render/frustum.hpp, as FrameRenderer culls).
    const Frustum frustum(viewProjection);
    for (int index : scene.transparentObjects()) {
        const Bounds& b = scene.objects()[std::size_t(index)].worldBounds;
        if (b.empty() || !frustum.mayContain(b)) continue;
        glm::vec2 lo(1e30f), hi(-1e30f);
        int behind = 0;
        for (int corner = 0; corner < 8; ++corner) {
            const glm::vec3 p((corner & 1) ? b.max.x : b.min.x, (corner & 2) ? b.max.y : b.min.y,
                              (corner & 4) ? b.max.z : b.min.z);
            const glm::vec4 c = viewProjection * glm::vec4(p, 1.0f);
            if (c.w <= 1e-6f) {
                ++behind;
                continue;
            }
            lo = glm::min(lo, glm::vec2(c) / c.w);
            hi = glm::max(hi, glm::vec2(c) / c.w);
        }
        if (behind == 8) continue;  // wholly behind the eye: nothing drawn
        if (behind > 0) {           // straddles the eye plane: it may cover anything
            area += full;
            continue;
        }
        lo = glm::clamp(lo, glm::vec2(-1.0f), glm::vec2(1.0f));
        hi = glm::clamp(hi, glm::vec2(-1.0f), glm::vec2(1.0f));
        const glm::vec2 extent = glm::max(hi - lo, glm::vec2(0.0f)) * 0.5f * glm::vec2(displaySize);
        area += double(extent.x) * double(extent.y);
    }
    return area;
}

ZoomCalibration calibrateZoomCost(Technique& technique, glm::ivec2 displaySize, int maxZoom,
                                  const std::function<void(const std::string&)>& progress) {
    ZoomCalibration calibration;
    FrameRenderer renderer;
    for (int layers : {1, 8}) {
        GpuScene scene(makeLayersScene(layers));
        const Camera camera = defaultCamera(scene.scene(), scene.objects());
        for (int zoom : {1, 2, 4}) {
            if (zoom > maxZoom) continue;
            if (progress)
                progress("zoom calibration: " + technique.info().id + ", layers:" + std::to_string(layers) + " at zoom " +
                         std::to_string(zoom));
            FrameOptions options;
            options.zoom = zoom;
            renderer.render(scene, camera, displaySize, &technique, options);  // warm-up: allocations
            ZoomCalibrationPoint point;
            point.layers = layers;
            point.zoom = zoom;
            point.ms = 1e300;
            for (int run = 0; run < 2; ++run) {
                const FrameResult r = renderer.render(scene, camera, displaySize, &technique, options);
                point.ms = std::min(point.ms, r.gpuMs);
                point.pixels = double(r.renderSize.x) * double(r.renderSize.y);
                point.fragments = double(fragmentsRasterized(r.stats));
            }
            gl::checkGl("zoom calibration");
            calibration.points.push_back(point);
        }
    }
    // Full fit; a negative slope (noise, or a cost that does not grow) is dropped and the rest refit.
    // At zoom 1 alone the pixels never vary: no per-pixel slope can be told from the fixed part.
    const bool pixelsVary = maxZoom >= 2;
    glm::dvec3 c = fitPlane(calibration.points, pixelsVary, true);
    if (c.y < 0.0 || c.z < 0.0) c = fitPlane(calibration.points, pixelsVary && c.y >= 0.0, c.z >= 0.0);
    calibration.model.fixedMs = std::max(0.0, c.x);
    calibration.model.msPerMegapixel = std::max(0.0, c.y);
    calibration.model.msPerMegafragment = std::max(0.0, c.z);
    double sum = 0.0;
    for (const auto& p : calibration.points) {
        const double e = calibration.model.predict(p.pixels, p.fragments) - p.ms;
        sum += e * e;
    }
    calibration.rmsResidualMs = calibration.points.empty() ? 0.0 : std::sqrt(sum / double(calibration.points.size()));
    return calibration;
}

}  // namespace strata
