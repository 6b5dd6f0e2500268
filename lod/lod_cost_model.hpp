#pragma once
// Predicted GPU time of one object drawn as geometry or as a layered impostor, on one device:
// the two curves of Schauffler's Fig. 8 (layered-impostors.md section 4). Geometry is
// vertex-bound (a dense model's triangles are smaller than a pixel, so its time grows with the
// triangle count and hardly with its screen size); an impostor is fill-bound (a stack of L
// textured, alpha-tested slice quads: its time grows with the screen area of the slices summed
// over the slices drawn, the "layer pixels", and not with the model's triangles). The
// crossover between the two is the paper's dashed lines.
//
// Times are per draw of one object, in milliseconds; counts in millions keep the coefficients
// readable (ms per million triangles, ms per million pixels).
#include <functional>
#include <string>
#include <vector>

namespace strata::lod {

struct LodCostModel {
    // Geometry: fixed + per triangle (vertex and triangle setup) + per covered pixel (shading
    // the fragments the model leaves on screen; small for a dense model). The fixed parts of both
    // models are one more draw's cost on the GPU or on the CPU that submits it, whichever is more
    // (lod_cost_calibration.cpp): a frame of many small draws waits for the CPU.
    double geometryFixedMs = 0.0;
    double geometryMsPerMegatriangle = 0.0;
    double geometryMsPerMegapixel = 0.0;
    // Impostor: a draw's fixed cost, shared by the stand-ins one instanced draw takes (stand-ins
    // of one impostor seen from the same view, GpuScene::drawObjects), + one more stand-in in
    // such a draw + per slice quad (each quad's vertices and its triangles' setup: a stand-in of
    // 64 slices draws about as many quads, which on llvmpipe cost more than its pixels once it is
    // small) + per layer pixel (each slice quad's screen area, summed over the slices drawn:
    // every such pixel is a texture fetch and an alpha test, kept or discarded).
    // A quad's cost grows with its side too (its partly covered pixel blocks, rasterised in full:
    // on llvmpipe a stand-in's 8 x 8 pixel quad costs about 3x its pixels at the large quads'
    // rate), so the model charges each quad's side, in pixels: sqrt(layer pixels / quads) a
    // quad, sqrt(layer pixels x quads) a stand-in.
    double impostorFixedMs = 0.0;
    double impostorInstanceMs = 0.0;
    double impostorMsPerKiloquad = 0.0;
    double impostorMsPerKilosidePx = 0.0;
    double impostorMsPerMegapixel = 0.0;

    // `draws`: the draw calls it takes (a LOD unit of several parts draws each), each paying the fixed cost.
    double geometryMs(double triangles, double coveredPixels, double draws = 1.0) const;
    // `quads`: the slice quads drawn; `draws`: its share of a draw (1 / the stand-ins that share it).
    double impostorMs(double layerPixels, double quads = 0.0, double draws = 1.0) const;
    // Of that, the quad sides' part: sqrt(layer pixels x quads) pixels of side.
    double impostorSideMs(double layerPixels, double quads) const;
};

// The layer pixels of an impostor of `slices` slices whose every slice fills a square of
// `sizePx` x `sizePx` pixels (the paper's measurement: a viewport-filling layered impostor),
// times `drawnFraction` (in (0, 1]: what the per-slice bounding rectangles leave of it, Fig. 6).
double impostorLayerPixels(double sizePx, int slices, double drawnFraction = 1.0);

// Fig. 8's crossover, for an object on screen as a square of `sizePx` x `sizePx` pixels drawn
// as an impostor of `slices` full slices (one quad each, a draw of its own) or as a model
// covering the same square:
// the triangle count above which the impostor is cheaper. 0 when the impostor is cheaper
// whatever the model (its cost is below the geometry's fixed part); +infinity when the model's
// triangles cost nothing on this device (no count makes the impostor cheaper).
double crossoverTriangles(const LodCostModel& model, double sizePx, int slices);

// The inverse: the size (pixels, side of the square) up to which an impostor of `slices` slices
// is cheaper than a model of `triangles` triangles, from size 0: the smallest positive root of
// (impostor - geometry)(s) = 0, a quadratic in s (pixels and quad sides). 0 when it is never
// cheaper; +infinity when it is cheaper at every size (its growth with the size never catches
// up with the geometry's margin). Where the impostor's pixels cost less than the geometry's but
// its sides cost more, it can be cheaper again above a second root, which this does not report.
double crossoverSizePx(const LodCostModel& model, double triangles, int slices);

// The predicted time to bake one layered impostor (lod/layered_impostor.hpp) of a
// `triangles` mesh: the mesh drawn once per (view, peel) and once per hole-filling pair, each a
// geometry draw into a `resolution`-square image (half of it covered: the slab frames the
// bounding sphere). What else a bake does (shader builds, the hole-filling quads and read-backs,
// rectangles) LodController scales in from the bakes it has measured; before any, by
// kBakeOverhead: on llvmpipe the Stanford bunny (69 k triangles, 20 views, 2 peels, 30 pairs)
// was predicted 575 ms from the draws and measured 1104 ms.
double predictedBakeMs(const LodCostModel& model, double triangles, int meshDraws, int resolution);
inline constexpr double kBakeOverhead = 2.0;

// ---- calibration on the current GL device ----

struct LodCalibrationPoint {
    enum class Kind { Geometry, Impostor } kind = Kind::Geometry;
    double triangles = 0.0;    // geometry: the mesh's triangles
    double pixels = 0.0;       // geometry: covered pixels (samples passed); impostor: layer pixels
    int slices = 0;            // impostor: quads in the stack
    int viewport = 0;          // side of the square viewport, pixels
    double ms = 0.0;           // GPU time of one draw (fastest of the timed repetitions)
};

struct LodCalibration {
    LodCostModel model;
    std::vector<LodCalibrationPoint> points;
    // Of each model over its own points. Geometry's fixed term is a marginal draw, not the fit's
    // intercept, so its residuals also hold each timed pass's own cost (about 1 ms on llvmpipe);
    // the impostor stacks' are against their fitted line (its intercept in place of a stand-in's
    // draw and instance).
    double geometryRmsResidualMs = 0.0;
    double impostorRmsResidualMs = 0.0;
    double wallMs = 0.0;                 // CPU wall time the calibration took
    bool kept = false;                   // read from an earlier run's (lod/lod_cost_cache.hpp), not measured now
    std::string device;                  // GL_RENDERER
};

// Measures the model on the current GL context (one must be current) in well under a second on
// llvmpipe, into its own small framebuffer (the caller's framebuffer binding, viewport and
// depth/blend/cull state are restored). Geometry: a dense procedural mesh (makeBumpyBlob) at two
// triangle counts (a 4x step), each at a tiny and a small viewport, covered pixels counted by a
// samples-passed query; impostor: a stack of alpha-tested textured quads
// (the frame's own opaque scene program with its impostor alpha test, common/scene_main.glsl) with two slice
// counts at two viewport areas for the per-pixel cost; a lone stand-in's marginal draw for the
// draw's fixed cost; stand-ins in one instanced draw (GpuScene::drawObjects), 256 against one and
// stacks of 32 quads against one quad, for the per-stand-in and per-quad costs. Each point: one warm-up draw, the fastest of three timed
// (gl::GpuTimer), each timed pass several draws averaged. Least squares per curve, slopes
// kept non-negative (a negative slope, from noise, is dropped and the rest refit).
LodCalibration calibrateLodCost(const std::function<void(const std::string&)>& progress = {});

}  // namespace strata::lod
