#pragma once
// `strata bench`: renders each requested technique and the exact reference over the same
// frames (a camera path or a fixed view), and reports cost (GPU ms from timer queries, CPU wall
// ms, passes, bytes) and loss (fragments captured against the shared count, RMSE/PSNR/max error
// against the reference in linear RGB). Warm-up frames are rendered and not recorded.
// Each frame is compared as soon as it is read back and only running sums are kept, so memory
// does not grow with the frame count. With a camera path, each technique frame is preceded by the
// reference frame for the same camera (untimed); with a fixed camera the reference renders once.
#include "camera/camera_path.hpp"
#include "frame/budget_governor.hpp"
#include "frame/zoom_controller.hpp"
#include "gl/context.hpp"
#include "image/image.hpp"
#include "oit/technique_settings.hpp"
#include "render/coplanarity.hpp"
#include "render/deflection_warp.hpp"
#include "render/gpu_scene.hpp"
#include "render/stand_in.hpp"

#include <nlohmann/json.hpp>

#include <array>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace strata {

// What stands in for objects in one bench frame (BenchOptions::lod).
struct BenchLodFrame {
    const StandIns* standIns = nullptr;
    int impostorObjects = 0;
    std::uint64_t impostorBytes = 0;
};

// One state of the frame budget's levers: a zoom and an index into the LOD ladder.
struct BudgetPin {
    int zoom = 1;
    int lodLevel = 0;
};
// "Z,L" (zoom 1..16, ladder level 0..levels-1); throws std::invalid_argument naming the format.
BudgetPin parseBudgetPin(const std::string& text, int ladderLevels);
// Throws std::invalid_argument, one line, where a pin cannot be drawn as asked: without a budget,
// a level above 0 without the LOD lever, a zoom above 1 without the zoom lever or above the
// budget's largest zoom.
void checkBudgetPin(const BudgetPin& pin, const std::optional<ZoomBudget>& budget, BudgetLevers levers);

struct BenchOptions {
    std::string sceneName;                  // as given on the command line
    std::vector<std::string> modes;         // technique ids; empty = all
    glm::ivec2 size{512, 512};
    int frames = 10;
    int warmupFrames = 2;
    std::optional<CameraPath> cameraPath;   // else the scene's default camera, fixed
    SettingsById settings;                  // from resolveSettings(benchModeIds(modes), ...); defaults where absent
    // Sees the first frame of each mode (the reference's too) with its id and the reference frame
    // it is compared against (for a reference row, the frame itself), e.g. to save both or their
    // error map; may be empty. The bench itself writes no files.
    std::function<void(const std::string& id, const Image& frame, const Image& reference)> firstFrame;
    // Sees the coplanarity heatmap of the first camera at the bench's size (the frame C_p is
    // measured on, render/coplanarity.hpp's colours); may be empty, and then none is read back.
    std::function<void(const Image& heatmap)> coplanarityHeatmap;
    std::function<void(const std::string&)> progress;  // one line per step, may be empty
    // Sees every reference frame the techniques are compared against, with its frame index, as
    // soon as it is read back; may be empty. The reference is what every error figure rests on,
    // so tests check these frames against the CPU ray cast (tests/bench_gl_test.cpp).
    std::function<void(int frame, const Image& reference)> referenceFrame;
    // Zoom rendering (render/zoom.hpp): techniques draw at 1/zoom of `size` and are enlarged
    // (zoomFilter: nearest replicates, bilinear blurs); the reference always draws at zoom 1, so
    // the error includes what the zoom loses. With `budget` a controller picks the zoom per frame
    // instead (the predictive one calibrated per technique first), and each mode reports its
    // per-frame zoom and time.
    int zoom = 1;
    DeflectFilter zoomFilter = DeflectFilter::Nearest;
    // The reference drawn at this many times the size each way and averaged down (1: one sample a
    // pixel, as every technique draws). Above 1 every row, the reference technique's own included,
    // is compared with that antialiased frame: the reference's row then shows what one sample a
    // pixel loses on this scene, the floor under every other row's loss
    // (scripts/aliasing_floor.sh, docs/results.md "the scene graph at scale").
    int referenceSupersample = 1;
    // After each timed frame, draw the same frame again (its stand-ins too) without the per-pass
    // timer queries and the fragment count, timed by the wall clock to a glFinish: how the peers
    // time themselves (../shared/tools/peers). On llvmpipe the pass timers drain the pipeline at
    // every pass edge, which the passes' summed GPU time pays for (docs/results.md, "Two clocks").
    // Not with a budget: its frames differ by what the controller chose.
    bool wallFrames = false;
    std::optional<ZoomBudget> budget;
    ZoomControllerKind zoomController = ZoomControllerKind::Reactive;
    // Per-object level of detail (lod/, which sits above core): called before each technique
    // frame with its camera, the bench size and how many frames that selection draws (the
    // warm-up's call draws warmupFrames); says what stands in for objects (null: all
    // geometry) and how many and how much. The reference always draws geometry, so the error
    // includes what the impostors lose. `lodReport` goes into the JSON as "lod" as given.
    // `maxErrorPx`: the LOD error bound for this frame (the frame budget's LOD lever); 0 keeps the
    // LOD options' own.
    std::function<BenchLodFrame(const Camera&, glm::ivec2 size, int frames, double maxErrorPx)> lod;
    nlohmann::json lodReport;
    // Under a budget with the LOD lever (frame/budget_governor.hpp): what LOD would do at each of
    // the ladder's bounds this frame (LodController::previewBounds); empty: no LOD lever.
    std::function<LodPreview(const Camera&, glm::ivec2 size, const std::vector<double>& boundsPx)> lodPreview;
    BudgetLevers levers{true, false};  // what the budget steers (the LOD lever needs lodPreview)
    LodLadder lodLadder;               // the bounds it steers among
    // Under a budget, every frame (warm-up included) drawn at this state instead of the governor's
    // choice: one state's frames, times and PSNRs along the path, for `scripts/bench_budget.sh
    // --oracle` (scripts/lib/budget_oracle.py), which finds the best state frame by frame. No
    // governor and no calibration.
    std::optional<BudgetPin> budgetPin;
};

// A run of consecutive frames over the budget's upper edge (target x (1 + band)).
struct BudgetExcursion {
    int firstFrame = 0;
    int frames = 0;
    double peakOverTarget = 0.0;   // the worst frame's time / target
};

struct BenchMode {
    std::string id;
    std::string family;
    std::string reference;  // the mode its error is measured against (benchReferenceOf)
    bool robust = false;
    bool handlesCoplanarity = false;
    bool rgbTransmittance = false;  // TechniqueInfo::rgbTransmittance
    double msMedian = 0, msP95 = 0;          // GPU ms of the technique's passes (opaque pass excluded)
    double cpuMsMedian = 0;                  // CPU wall ms of the whole frame
    double wallMsMedian = -1;                // BenchOptions::wallFrames: the untimed frames' wall ms (-1: none)
    double threadCpuMsMedian = 0;            // CPU ms of the rendering thread (FrameResult::threadCpuMs)
    double drawCallsMedian = 0;              // GL draws of scene objects per frame (all passes)
    double lodMsMedian = 0;                  // CPU ms of the frame's LOD step (BenchOptions::lod), 0 without
    double opaqueMsMedian = 0;               // GPU ms of the opaque pass, for scale
    int passes = 0;
    std::uint64_t bytes = 0;
    std::uint64_t fragmentsTotal = 0;        // summed over frames, the shared count
    std::uint64_t fragmentsCaptured = 0;     // summed over frames
    double robustnessRatio = 1.0;
    bool overflowed = false;
    int regrows = 0;
    int tiles = 1;
    std::uint64_t objectDraws = 0;           // summed over frames
    std::uint64_t objectDrawsSkipped = 0;    // summed over frames
    std::uint64_t objectsCulled = 0;         // outside the view frustum, summed over frames
    std::uint64_t unitsCulled = 0;           // LOD unit instances wholly outside, summed over frames
    std::uint64_t fragmentsTail = 0;         // summed over frames
    std::uint64_t fragmentsDropped = 0;      // summed over frames: counted but not stored
    std::uint64_t primitivesBounded = 0;     // summed over frames: sampled coarser than asked
    double rmse = 0, psnr = 100, maxAbsError = 0;
    std::vector<std::pair<std::string, double>> passMsMedian;  // per pass name
    std::vector<SettingDescription> settingDescriptions;       // what the mode ran with
    SettingValues settings;
    // The whole frame's GPU time (opaque pass, technique, enlargement): what a zoom speeds up.
    double frameMsMedian = 0.0;
    // The frame from its first GPU stamp to its last (FrameResult::gpuSpanMs): idle gaps between
    // passes in, passes overlapping (issued ahead) counted once.
    double frameSpanMsMedian = 0.0;
    double enlargeMsMedian = 0.0;
    int zoom = 1;                                             // fixed zoom (0 under a controller)
    // Under a frame budget (BenchOptions::budget): per frame, the zoom, the frame time and the
    // controller's prediction (NaN-free: 0 where it had none), and how the times met the target.
    std::vector<int> frameZoom;
    std::vector<double> frameMs, framePredictedMs;
    // Also per frame under a budget: the objects drawn as impostors, and the PSNR of the frame
    // against the same technique's frame without a budget (zoom 1, geometry; 100 when equal).
    std::vector<int> frameImpostorObjects;
    std::vector<double> framePsnr;
    // And the LOD error bound each frame used (0: the LOD options' own, no LOD lever), and the
    // governor's loss for its state (budget_governor.hpp's rule, display pixels).
    std::vector<double> frameLodBoundPx, frameLossPx;
    BudgetHits budgetHits;
    std::vector<BudgetExcursion> excursions;
    ZoomCostModel calibratedModel;                            // what calibration fitted (budgetNeedsCalibration)
    // Under BenchOptions::lod: the most objects drawn as impostors in one frame, and the most
    // impostor memory one frame used.
    int impostorObjects = 0;
    std::uint64_t impostorBytes = 0;
};

struct BenchReport {
    std::string scene;
    glm::ivec2 size{0, 0};
    int frames = 0;
    gl::DeviceInfo device;
    std::string reference = "abuffer";
    std::vector<BenchMode> modes;
    // C_p: the share of pixels with transparent fragments where two or more share a depth layer
    // under the reference's tie rule (the GPU coplanarity detector, render/coplanarity.hpp).
    double coplanarityProbability = 0.0;
    double coplanarityOnePerLayerRobustness = 1.0;  // layers / fragments: R_h of plain f2b, dual, bun
    std::array<std::uint64_t, kCoplanarityBins> pixelsByLargestLayer{};  // the heatmap's histogram
    std::size_t triangles = 0;     // drawn, over the objects
    std::size_t textureBytes = 0;  // decoded textures on the GPU, mip levels included
    std::size_t objects = 0;
    // Distinct meshes (a mesh placed by N objects is one), their triangles and GPU bytes.
    std::size_t meshes = 0, meshTriangles = 0, meshBytes = 0;
    int zoom = 1;
    std::string zoomFilter = "nearest";
    int referenceSupersample = 1;
    std::optional<ZoomBudget> budget;
    std::string zoomController;        // "reactive", "predictive" or "pinned" under a budget
    std::string budgetLevers;          // "zoom", "lod" or "zoom,lod" under a budget
    std::optional<BudgetPin> budgetPin; // BenchOptions::budgetPin
    nlohmann::json lod;                // BenchOptions::lodReport (null without LOD)
    // A signal stopped the run: `modes` are those that completed, of `modesPlanned`.
    bool interrupted = false;
    std::size_t modesPlanned = 0;
};

// Maximal runs of frames over targetMs x (1 + band).
std::vector<BudgetExcursion> budgetExcursions(const std::vector<double>& ms, double targetMs, double band);

// The techniques a bench of `modes` renders (empty: all), the reference first: the set its
// settings are resolved against. Throws std::invalid_argument for an unknown id.
std::vector<std::string> benchModeIds(const std::vector<std::string>& modes);

// The technique a mode's error is measured against: abuffer-volume for the volumetric family
// (whose model draws volumes as media), abuffer for every other.
std::string benchReferenceOf(const std::string& id);

// Needs a current GL context. Throws std::invalid_argument for an unknown mode. Stops early when
// SIGINT or SIGTERM arrives (io/interrupt.hpp): the report then holds the techniques that
// completed every frame, and says `interrupted`.
BenchReport runBench(const GpuScene& scene, const BenchOptions& options);

nlohmann::json benchToJson(const BenchReport& report);
std::string benchToTable(const BenchReport& report);
std::string benchToCsv(const BenchReport& report);

// The floor row's median GPU time, when the run measured one (it is in the registry, so `--modes
// all` includes it): every technique's time is also given as a multiple of it ("x floor").
std::optional<double> floorMs(const BenchReport& report);

// One number through a printf format ("%.2f"): the report's and the table's figures.
std::string formatNumber(const char* format, double value);

// "2.4 MiB", "250.0 KiB", "12 B": memory as the table shows it.
std::string humanBytes(std::uint64_t bytes);

}  // namespace strata
