#pragma once
// The per-object LOD decision (issue 11, "LOD in the scene graph"): geometry or layered
// impostor for each object this frame, from the cost model calibrated on this device
// (lod/lod_cost_model.hpp) under a screen-space error bound (lod/lod_error.hpp). Pure: no GL,
// no scene graph; the caller fills one LodObjectInput per object and reads one LodDecision back.
//
// Rules, in order (the first that applies decides):
//  1. an object with no triangles: geometry (nothing to replace);
//  2. the eye inside the bounding sphere, or closer than kTooCloseRadii radii to its centre:
//     geometry, in every mode. The impostor is baked for viewers outside the sphere: inside it
//     there is no image of what surrounds the eye, and near it the object spans more than 60
//     degrees of view (half-angle asin(1/2)), its slices are seen at grazing angles and tear,
//     and the parallax error (lod_error.hpp) is a large part of the screen;
//  3. mode Geometry: geometry (forced);
//  4. no impostor baked for the object: geometry;
//  5. mode Impostors: impostor (forced, whatever its error or cost);
//  6. mode Auto: error above maxErrorPx: geometry; else the cheaper of the two predictions
//     (ties go to geometry: exact for the same cost). The impostor's prediction is that of the
//     cheapest of its levels of merged slices whose error is within the bound (level 0, the
//     baked slices, when no coarser one is) and, with LodSelectOptions::levelBasePx, adds at
//     most maxErrorPx - levelBasePx to level 0's; forced impostors draw level 0.
#include "lod/lod_cost_model.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace strata {
struct Camera;
}

namespace strata::lod {

enum class LodMode { Geometry, Impostors, Auto };

// "geometry", "impostors", "auto"; anything else throws std::invalid_argument:
//   lod mode 'X' is not one of geometry|impostors|auto
LodMode parseLodMode(std::string_view text);
const char* to_string(LodMode mode);

// The distance, in bounding radii, under which an object is "too close" for its impostor.
inline constexpr double kTooCloseRadii = 2.0;
// The classic engines' switch: an impostor is acceptable while its error stays under ~4 px.
inline constexpr double kDefaultMaxErrorPx = 4.0;

// What selection needs to know of an object's impostor this frame.
struct ImpostorSummary {
    int id = -1;                   // which impostor (lod/impostor_set.hpp's keys: instances share one); -1: its own
    int slices = 1;                // L
    int resolution = 64;           // texels a side of each view's image
    double overlap = 0.5;          // as the bake used it (0 with peels > 1): lod_error.hpp
    double apexHalfAngleRadians = 0.3398369094541219;  // asin(1 / 3): the default apex at 3r
    double viewAngleRadians = 0.0; // from the eye direction to the nearest baked view
    std::uint64_t bytes = 0;       // its memory (Table 2's formula + rectangles)
    double drawnFraction = 1.0;    // of the full slice squares actually drawn (per-slice rectangles)
    int peels = 1;                 // images per view (2 for a transparent mesh): drawnFraction <= peels
    // The slice quads drawn from the nearest view (its non-empty slices and the hole-closing
    // slices of its neighbours, LayeredImpostor::drawFor); 0: one per slice.
    double quads = 0.0;
    // The coarser levels of merged slices (LayeredImpostor::levels), each with the same three
    // figures as level 0 above; auto draws the cheapest level whose error is within the bound.
    struct Level {
        int slices = 1;
        double drawnFraction = 1.0;
        double quads = 0.0;
    };
    static constexpr int kMaxCoarserLevels = 6;  // 256 slices down to 8
    std::array<Level, kMaxCoarserLevels> coarser{};
    int coarserLevels = 0;
};

// One object, or a LOD unit of several (lod/lod_units.hpp) decided as one.
struct LodObjectInput {
    glm::vec3 center{0.0f};        // world bounding sphere
    float radius = 0.0f;
    std::uint64_t triangles = 0;
    int objects = 1;               // scene objects it stands for (LodSelection::impostorObjects)
    // The draws its geometry costs, each paying the model's fixed cost: a part whose mesh and
    // material k objects share goes out in one instanced draw with them (GpuScene::drawObjects)
    // and pays 1/k of one. 0: one per object. A stand-in's share is standInDraws.
    double geometryDraws = 0.0;
    double drawsForGeometry() const { return geometryDraws > 0.0 ? geometryDraws : double(std::max(objects, 1)); }
    // Its stand-in's share of a draw: stand-ins of one impostor seen from the same view go out in
    // one instanced draw (GpuScene::drawObjects), so k units of an impostor with D distinct
    // draws among them pay D / k each. 1: a draw of its own. LodController estimates it as if
    // every unit of the impostor were a stand-in: where few are, each is charged less of a draw
    // than it takes (a few microseconds of fixed cost, against a stand-in's quads and pixels).
    double standInDraws = 1.0;
    bool hasImpostor = false;
    // Auto leaves transparent objects geometry; only --lod impostors draws them as impostors.
    // Their composite is what the techniques are compared on, and an impostor moves each
    // surface to its slice plane (within half a slice): orders within a slice, and so the
    // blend, can change where the techniques' exact answers would not.
    bool transparent = false;
    // The impostor bake keeps normals, depths and the base colour texture, COLOR_0 and MASK
    // (kSceneBakedDetail); a material with other textures (metallic-roughness, normal,
    // occlusion, emissive) would lose them. Auto leaves such objects geometry.
    bool materialNotBaked = false;
    ImpostorSummary impostor;
};

struct LodView {
    glm::vec3 eye{0.0f};
    double fovYRadians = 0.8726646259971648;  // 50 degrees
    glm::ivec2 imageSize{1, 1};
};
LodView lodView(const Camera& camera, glm::ivec2 imageSize);

struct LodSelectOptions {
    LodMode mode = LodMode::Auto;
    double maxErrorPx = kDefaultMaxErrorPx;
    // Where a frame budget steers the bound: the bound at which no coarser level is taken. A
    // level of merged slices may then add at most maxErrorPx - levelBasePx to the baked level's
    // error, so levels come only with the budget's raise of the bound, and without it each
    // stand-in draws its baked slices. 0: any level within maxErrorPx.
    double levelBasePx = 0.0;
};

enum class LodReason {
    NoTriangles,      // geometry: nothing to replace
    EyeInside,        // geometry: the eye is inside the bounding sphere
    TooClose,         // geometry: the eye is within kTooCloseRadii radii of the centre
    GeometryForced,   // geometry: mode geometry
    NoImpostor,       // geometry: none baked for this object
    ImpostorsForced,  // impostor: mode impostors
    ErrorAboveBound,  // geometry: the impostor's error exceeds maxErrorPx
    GeometryCheaper,  // geometry: predicted no slower than the impostor
    ImpostorCheaper,  // impostor: predicted faster, error within the bound
    TransparentAuto,  // geometry: transparent, and the mode is auto (LodObjectInput::transparent)
    MaterialAuto,     // geometry: a texture the bake does not keep (kSceneSurfaceDetail less kSceneBakedDetail: metallic-roughness, normal, occlusion, emissive), and the mode is auto
};
const char* to_string(LodReason reason);

struct LodDecision {
    bool impostor = false;
    LodReason reason = LodReason::GeometryForced;
    double distance = 0.0;       // eye to the bounding sphere's centre
    double projectedPx = 0.0;    // projected diameter of the bounding sphere (infinite inside)
    // Predictions: geometry covers the sphere's disc (pi/4 d^2 pixels), each impostor slice the
    // square d x d (times drawnFraction), both clipped to the image's area.
    double geometryMs = 0.0;     // predicted for every object
    double impostorMs = 0.0;     // predicted when it has an impostor and the eye is outside 2 r
    double errorPx = 0.0;        // the impostor's error bound (0 without an impostor)
    double layerPixels = 0.0;    // the impostor's predicted layer pixels (0 without one)
    double quads = 0.0;          // the impostor's predicted quads (0 without one)
    double parallaxPx = 0.0, samplingPx = 0.0;
    int level = 0;               // the impostor's level of merged slices (ImpostorSummary::coarser)
};

// One line saying why, e.g. "too close: distance 1.50 < 2 x radius 1.00" or
// "impostor cheaper: 0.120 ms < geometry 0.800 ms, error 2.1 px <= 4 px".
std::string explain(const LodDecision& decision, const LodObjectInput& object, const LodSelectOptions& options);

struct LodSelection {
    std::vector<LodDecision> objects;     // one per input, same order (LodController::selection(): per scene object)
    int impostorObjects = 0;              // objects drawn as impostors
    int impostorsUsed = 0;                // distinct impostors among them (by id; -1 counts each)
    std::uint64_t impostorBytes = 0;      // memory of the impostors used, each shared one once
    double predictedMs = 0.0;             // sum of the chosen predictions
    double geometryOnlyMs = 0.0;          // sum of the geometry predictions (all geometry)
};

LodSelection selectLod(const std::vector<LodObjectInput>& objects, const LodView& view, const LodCostModel& model,
                       const LodSelectOptions& options = {});

// One object's decision (what selectLod does per object).
LodDecision selectLodFor(const LodObjectInput& object, const LodView& view, const LodCostModel& model,
                         const LodSelectOptions& options = {});

}  // namespace strata::lod
