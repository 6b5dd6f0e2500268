// The joint frame budget (frame/budget_governor.hpp) on a synthetic device whose frame time is
// known exactly: t(z, k) = 2 ms + 40 ms per million pixels at zoom z + LOD level k's time (fixed,
// geometry-bound: no part of it scales with pixels). At 1280x720 the zoom part is 38.864 ms at
// z = 1, 11.216 at z = 2, 6.099 at z = 3, 4.304 at z = 4 (zoomPixels of 1280x720, 640x360,
// 427x240, 320x180); the four LOD levels (bounds 4, 8, 16, 32 px) take 30, 18, 10 and 6 ms.
#include "bench/bench.hpp"
#include "frame/budget_governor.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <vector>

using namespace strata;

namespace {

struct Device {
    ZoomCostModel cost{2.0, 40.0, 0.0};
    glm::ivec2 display{1280, 720};
    std::vector<double> lodMs{30.0, 18.0, 10.0, 6.0};
    std::vector<double> lodLossPx{0.0, 0.2, 0.6, 1.5};
    // The part of each level's time the preview says scales with pixels (none by default), and
    // what that part really costs over the preview's figure.
    std::vector<double> lodPixelMs{0.0, 0.0, 0.0, 0.0};
    double lodPixelTruth = 1.0;
    // Time every level really takes beyond what the preview says (geometry it undercounts).
    double unseenMs = 0.0;
    // Transparent fragments per pixel drawn (cost.msPerMegafragment charges them).
    double fragmentsPerPixel = 0.0;
    double fragments(int zoom) const { return fragmentsPerPixel * zoomPixels(display, zoom); }
    double coverage = 1.0;
    double zoomMs(int zoom) const { return cost.predict(zoomPixels(display, zoom), fragments(zoom)); }
    double ms(int zoom, int level) const {
        const std::size_t k = std::size_t(level);
        return zoomMs(zoom) + lodMs[k] + unseenMs - lodPixelMs[k] + lodPixelTruth * lodPixelMs[k] / double(zoom * zoom);
    }
    GovernorLoad load(int floor = 1) const {
        GovernorLoad l;
        l.zoom = FrameLoad{display, 0.0, floor};
        l.lod.coverage = coverage;
        LodLadder ladder;
        for (std::size_t k = 0; k < lodMs.size(); ++k)
            l.lod.levels.push_back({ladder.bound(int(k)), lodMs[k], lodPixelMs[k], lodLossPx[k], 0});
        return l;
    }
};

ZoomBudget budgetOf(double targetMs, int maxZoom = 4) {
    ZoomBudget b;
    b.targetMs = targetMs;
    b.maxZoom = maxZoom;
    return b;
}

struct Run {
    std::vector<GovernorChoice> choices;
    std::vector<double> ms;
    double meanLoss() const {
        double sum = 0.0;
        for (const auto& c : choices) sum += c.lossPx;
        return sum / double(choices.size());
    }
};

Run drive(BudgetGovernor& governor, const Device& device, int frames, int floor = 1) {
    Run run;
    for (int f = 0; f < frames; ++f) {
        const GovernorLoad load = device.load(floor);
        const GovernorChoice c = governor.choose(load);
        const double t = device.ms(c.zoom, c.lodLevel);
        governor.observe(FrameCost{c.zoom, t, std::uint64_t(device.fragments(c.zoom)), load.zoom});
        run.choices.push_back(c);
        run.ms.push_back(t);
    }
    return run;
}

}  // namespace

TEST_CASE("budget governor: the synthetic device's times, and the levers and ladder parsed") {
    const Device d;
    CHECK(d.zoomMs(1) == doctest::Approx(38.864));
    CHECK(d.zoomMs(2) == doctest::Approx(11.216));
    CHECK(d.zoomMs(3) == doctest::Approx(6.0992));
    CHECK(d.zoomMs(4) == doctest::Approx(4.304));
    CHECK(parseBudgetLevers("zoom").zoom);
    CHECK_FALSE(parseBudgetLevers("zoom").lod);
    CHECK_FALSE(parseBudgetLevers("lod").zoom);
    CHECK((parseBudgetLevers("lod,zoom").zoom && parseBudgetLevers("zoom,lod").lod));
    CHECK(to_string(parseBudgetLevers("lod,zoom")) == "zoom,lod");
    for (const char* bad : {"", "zoom,", "LOD", "zoom,lod,zoom", "technique"})
        CHECK_THROWS_WITH_AS(parseBudgetLevers(bad), doctest::Contains("not one of zoom|lod|zoom,lod"), std::invalid_argument);
    CHECK(parseBudgetPin("2,1", 4).zoom == 2);
    CHECK(parseBudgetPin("2,1", 4).lodLevel == 1);
    CHECK(parseBudgetPin("16,3", 4).lodLevel == 3);
    for (const char* bad : {"", "2", "0,0", "17,0", "2,4", "2,-1", "2,1x", "x,1", ",1"})
        CHECK_THROWS_WITH_AS(parseBudgetPin(bad, 4), doctest::Contains("expected ZOOM,LEVEL"), std::invalid_argument);
    CHECK(LodLadder{}.bounds() == std::vector<double>{4.0, 8.0, 16.0, 32.0});
    CHECK(LodLadder{1.5, 3}.bounds() == std::vector<double>{1.5, 3.0, 6.0});
    CHECK(zoomLossPx(1) == 0.0);
    CHECK(zoomLossPx(2) == 0.5);
    CHECK(zoomLossPx(4) == 1.5);
    CHECK_THROWS_AS(BudgetGovernor(budgetOf(10), {false, false}, ZoomControllerKind::Predictive, {}),
                    std::invalid_argument);
}

TEST_CASE("budget governor: predictive picks the least loss that fits, whichever lever that is") {
    Device d;
    // Budget 50 ms. Fitting states and their loss (coverage 1): (2, 0) 41.216 ms, 0.5 px;
    // (1, 2) 48.864 ms, 0.6 px; (2, 1) 29.216 ms, 0.7 px; ... (1, 0) takes 68.864 and (1, 1) 56.864.
    BudgetGovernor zoomWins(budgetOf(50), {true, true}, ZoomControllerKind::Predictive, d.cost);
    GovernorChoice c = zoomWins.choose(d.load());
    CHECK(c.zoom == 2);
    CHECK(c.lodLevel == 0);
    CHECK(c.predictedMs == doctest::Approx(41.216));
    CHECK(c.lossPx == doctest::Approx(0.5));

    // LOD's loss at 16 px made smaller than the zoom's: the same budget goes to the LOD lever.
    d.lodLossPx = {0.0, 0.1, 0.3, 1.0};
    BudgetGovernor lodWins(budgetOf(50), {true, true}, ZoomControllerKind::Predictive, d.cost);
    c = lodWins.choose(d.load());
    CHECK(c.zoom == 1);
    CHECK(c.lodLevel == 2);
    CHECK(c.predictedMs == doctest::Approx(48.864));
    CHECK(c.lossPx == doctest::Approx(0.3));

    // Half the display covered: the zoom's loss halves (0.25 px), and the zoom wins again.
    d.coverage = 0.5;
    BudgetGovernor halfCovered(budgetOf(50), {true, true}, ZoomControllerKind::Predictive, d.cost);
    c = halfCovered.choose(d.load());
    CHECK(c.zoom == 2);
    CHECK(c.lodLevel == 0);
    CHECK(c.lossPx == doctest::Approx(0.25));
}

TEST_CASE("budget governor: one lever alone, the head-speed floor, and a budget nothing meets") {
    const Device d;
    // LOD alone: the zoom stays 1, the bound goes to 16 px (48.864 ms); the floor raises the zoom.
    BudgetGovernor lod(budgetOf(50), {false, true}, ZoomControllerKind::Predictive, d.cost);
    GovernorChoice c = lod.choose(d.load());
    CHECK(c.zoom == 1);
    CHECK(c.lodLevel == 2);
    c = lod.choose(d.load(3));
    CHECK(c.zoom == 3);
    CHECK(c.lodLevel == 0);  // 6.099 + 30 fits: nothing lossier needed
    // Joint with a floor of 3: never below it.
    BudgetGovernor joint(budgetOf(50), {true, true}, ZoomControllerKind::Predictive, d.cost);
    CHECK(joint.choose(d.load(3)).zoom == 3);
    // 5 ms: nothing fits (the fastest is 4.304 + 6 = 10.304 ms at zoom 4, 32 px): the fastest state.
    BudgetGovernor tight(budgetOf(5), {true, true}, ZoomControllerKind::Predictive, d.cost);
    c = tight.choose(d.load());
    CHECK(c.zoom == 4);
    CHECK(c.lodLevel == 3);
    CHECK(c.predictedMs == doctest::Approx(10.304));
}

TEST_CASE("budget governor: the zoom lever alone is today's zoom controller, frame for frame") {
    const Device d;
    for (ZoomControllerKind kind : {ZoomControllerKind::Reactive, ZoomControllerKind::Predictive}) {
        CAPTURE(zoomControllerName(kind));
        // The device's LOD stays at level 0: its 30 ms are a fixed part the zoom cannot touch.
        ZoomCostModel model = d.cost;
        model.fixedMs += d.lodMs[0];
        BudgetGovernor governor(budgetOf(45, 8), {true, false}, kind, model);
        auto controller = makeZoomController(kind, budgetOf(45, 8), model);
        for (int f = 0; f < 40; ++f) {
            const GovernorLoad load = d.load();
            const GovernorChoice c = governor.choose(load);
            const int z = controller->choose(load.zoom);
            REQUIRE(c.zoom == z);
            CHECK(c.lodLevel == 0);
            governor.observe(FrameCost{z, d.ms(z, 0), 0, load.zoom});
            controller->observe(FrameCost{z, d.ms(z, 0), 0, load.zoom});
        }
    }
}

TEST_CASE("budget governor: reactive settles on the least loss within the budget, and holds it") {
    for (const std::vector<double>& lodLoss : {std::vector<double>{0.0, 0.2, 0.6, 1.5}, std::vector<double>{0.0, 0.1, 0.3, 1.0}}) {
        Device d;
        d.lodLossPx = lodLoss;
        CAPTURE(lodLoss[2]);
        BudgetGovernor governor(budgetOf(50), {true, true}, ZoomControllerKind::Reactive, d.cost);
        const Run run = drive(governor, d, 60);
        // It starts at the least lossy state, (1, 0) at 68.864 ms, and leaves it after one hold.
        CHECK(run.choices.front().zoom == 1);
        CHECK(run.choices.front().lodLevel == 0);
        // The last 40 frames: one state, the predictive rule's (zoom 2 or the 16 px bound), on budget.
        const GovernorChoice& last = run.choices.back();
        const bool lodCheaper = lodLoss[2] < 0.5;
        CHECK(last.zoom == (lodCheaper ? 1 : 2));
        CHECK(last.lodLevel == (lodCheaper ? 2 : 0));
        for (std::size_t f = 20; f < run.choices.size(); ++f) {
            CHECK(run.choices[f].zoom == last.zoom);
            CHECK(run.choices[f].lodLevel == last.lodLevel);
            CHECK(run.ms[f] <= 50.0 * 1.1);
        }
    }
}

TEST_CASE("budget governor: both levers lose less than either alone, for both policies") {
    // Budget 30 ms. Zoom alone (LOD at 4 px, 30 ms fixed) can never meet it and ends at zoom 4
    // (34.3 ms), 1.5 px; LOD alone (zoom 1) ends at 32 px, 44.9 ms over budget, 1.5 px; both: zoom 2 at 8 px
    // (29.216 ms, 0.5 + 0.2 px) is the least loss that fits.
    const Device d;
    for (ZoomControllerKind kind : {ZoomControllerKind::Reactive, ZoomControllerKind::Predictive}) {
        CAPTURE(zoomControllerName(kind));
        BudgetGovernor zoom(budgetOf(30), {true, false}, kind, [&] {
            ZoomCostModel m = d.cost;
            m.fixedMs += d.lodMs[0];
            return m;
        }());
        BudgetGovernor lod(budgetOf(30), {false, true}, kind, d.cost);
        BudgetGovernor both(budgetOf(30), {true, true}, kind, d.cost);
        const Run z = drive(zoom, d, 60), l = drive(lod, d, 60), b = drive(both, d, 60);
        CHECK(b.choices.back().zoom == 2);
        CHECK(b.choices.back().lodLevel == 1);
        CHECK(b.ms.back() <= 30.0);
        CHECK(z.ms.back() > 30.0);
        CHECK(l.ms.back() > 30.0);
        CHECK(b.choices.back().lossPx < z.choices.back().lossPx);
        CHECK(b.choices.back().lossPx < l.choices.back().lossPx);
        // Frames over the band's edge: predictive none; reactive one, the first at (1, 0) (68.9 ms,
        // over twice the target: judged at once). Reactive estimates each state as the time
        // measured plus the two models' difference (here the device's own model, so exactly):
        // (2, 0) at 41.2 ms (no fit) and (2, 1) at 29.2, which fits. Before the zoom model, with
        // the pixel share assumed whole, (2, 0) was estimated at 17.2 ms and two more frames went
        // over at its 41.2 (the undercount test below runs that path, without a model).
        int over = 0;
        for (double t : b.ms) over += t > 33.0;
        CHECK(over == (kind == ZoomControllerKind::Predictive ? 0 : 1));
        if (kind == ZoomControllerKind::Reactive) {
            CHECK(b.choices[1].zoom == 2);
            CHECK(b.choices[1].lodLevel == 1);
        }
    }
}

TEST_CASE("budget governor: LOD's pixel part shrinks with the zoom in the prediction") {
    // Level 0 takes 30 ms, 20 of them the impostors' and geometry's pixels: at zoom 2 it predicts
    // 10 + 20 / 4 = 15 ms, so (2, 0) is 11.216 + 15 = 26.216 ms and fits a 30 ms budget at 0.5 px.
    Device d;
    GovernorLoad load = d.load();
    load.lod.levels[0].pixelMs = 20.0;
    BudgetGovernor governor(budgetOf(30), {true, true}, ZoomControllerKind::Predictive, d.cost);
    const GovernorChoice c = governor.choose(load);
    CHECK(c.zoom == 2);
    CHECK(c.lodLevel == 0);
    CHECK(c.predictedMs == doctest::Approx(26.216));
    // Without a preview (LOD not in auto mode this frame) the bound is no lever and LOD adds
    // nothing predicted: zoom 1 (38.864 ms) misses, zoom 2 (11.216 ms) fits.
    GovernorLoad noLod = d.load();
    noLod.lod = {};
    BudgetGovernor zoomOnly(budgetOf(30), {true, true}, ZoomControllerKind::Predictive, d.cost);
    const GovernorChoice z = zoomOnly.choose(noLod);
    CHECK(z.lodLevel == 0);
    CHECK(z.zoom == 2);
    CHECK(z.predictedMs == doctest::Approx(11.216));
}

TEST_CASE("budget governor: reactive judges a frame over twice the target at once, not after its hold") {
    // Settled at (1, 2), 48.864 ms under a 50 ms budget; then the load jumps: every LOD level
    // costs 70 ms more (a dense view), so (1, 2) takes 118.9 ms, over twice the target.
    Device d;
    d.lodLossPx = {0.0, 0.1, 0.3, 1.0};
    BudgetGovernor governor(budgetOf(50), {true, true}, ZoomControllerKind::Reactive, d.cost);
    Run settled = drive(governor, d, 20);
    REQUIRE(settled.choices.back().zoom == 1);
    REQUIRE(settled.choices.back().lodLevel == 2);
    for (double& ms : d.lodMs) ms += 70.0;
    const GovernorLoad load = d.load();
    GovernorChoice c = governor.choose(load);
    governor.observe(FrameCost{c.zoom, d.ms(c.zoom, c.lodLevel), 0, load.zoom});
    // The very next frame is already lossier (without the rule it would wait for 4 frames).
    c = governor.choose(d.load());
    CHECK((c.zoom > 1 || c.lodLevel > 2));
}

TEST_CASE("budget governor: predictive learns what LOD's pixels really cost, then keeps within the band") {
    // The preview says 20 of level 0's 30 ms scale with pixels (12, 6 and 3 of the others'); the
    // device spends three times that. Believing the preview, the governor picks a state that
    // takes longer than it predicts, and the offset alone cannot fix a part that shrinks with
    // the zoom: the frames drawn at two zooms show it, and the fitted factor is the device's.
    // Measured: 2 of the first 10 frames over the band, none after; settled at zoom 2, 8 px:
    // 11.216 + (18 - 12) + 3 x 12 / 4 = 26.216 ms, predicted exactly.
    Device d;
    d.lodPixelMs = {20.0, 12.0, 6.0, 3.0};
    d.lodPixelTruth = 3.0;
    BudgetGovernor governor(budgetOf(30), {true, true}, ZoomControllerKind::Predictive, d.cost);
    CHECK(governor.lodPixelScale() == 1.0);
    // The premise: the first choice, on the preview alone, takes longer than predicted.
    {
        BudgetGovernor fresh(budgetOf(30), {true, true}, ZoomControllerKind::Predictive, d.cost);
        const GovernorChoice first = fresh.choose(d.load());
        CHECK(d.ms(first.zoom, first.lodLevel) > first.predictedMs + 1.0);
    }
    const Run run = drive(governor, d, 60);
    CHECK(governor.lodPixelScale() == doctest::Approx(3.0).epsilon(0.01));
    int earlyOver = 0, lateOver = 0;
    for (std::size_t f = 0; f < run.ms.size(); ++f) (f < 10 ? earlyOver : lateOver) += run.ms[f] > 33.0;
    MESSAGE("over the band: " << earlyOver << " of the first 10 frames, " << lateOver << " of the last 50; settled at zoom "
                              << run.choices.back().zoom << ", level " << run.choices.back().lodLevel << ", "
                              << run.ms.back() << " ms, predicted " << run.choices.back().predictedMs);
    CHECK(lateOver == 0);
    CHECK(run.choices.back().predictedMs == doctest::Approx(run.ms.back()).epsilon(0.01));
    // Where the preview is right the factor stays 1.
    d.lodPixelTruth = 1.0;
    BudgetGovernor right(budgetOf(30), {true, true}, ZoomControllerKind::Predictive, d.cost);
    drive(right, d, 60);
    CHECK(right.lodPixelScale() == doctest::Approx(1.0).epsilon(0.01));
}

TEST_CASE("budget governor: the reactive prior pixel share, of the time at zoom 1") {
    // The synthetic device at (1, 0): 68.864 ms of which LOD's 30 is fixed: 38.864 / 68.864.
    CHECK(priorPixelShare(68.864, 30.0, 1.0) == doctest::Approx(38.864 / 68.864));
    // At (2, 1): 29.216 ms drawn at a quarter of the pixels, 18 fixed: the pixel part at zoom 1
    // is 11.216 x 4 = 44.864, so 44.864 / 62.864 (the device's truth: 38.864 of 56.864, the zoom
    // part's own 2 ms being fixed too). Taken of the time at zoom 2 it would be 11.216 / 29.216.
    CHECK(priorPixelShare(29.216, 18.0, 0.25) == doctest::Approx(44.864 / 62.864));
    // A frame that is all fixed, or more than all: the least share; nothing known: 1.
    CHECK(priorPixelShare(20.0, 20.0, 1.0) == doctest::Approx(0.02));
    CHECK(priorPixelShare(20.0, 35.0, 0.25) == doctest::Approx(0.02));
    CHECK(priorPixelShare(20.0, 0.0, 0.25) == doctest::Approx(1.0));
    CHECK(priorPixelShare(0.0, 5.0, 1.0) == 1.0);
    CHECK(priorPixelShare(NAN, 5.0, 1.0) == 1.0);
    CHECK(priorPixelShare(20.0, NAN, 1.0) == 1.0);
    CHECK(priorPixelShare(20.0, 5.0, 0.0) == 1.0);
}

TEST_CASE("budget governor: reactive with a calibrated zoom model does not promise the zoom what the preview missed") {
    // The field's frames near the eye: every LOD level takes 15 ms more than its preview says
    // (geometry it undercounts), and the technique's own pixels are few (2 ms + 4 ms per
    // million pixels: 5.686 ms at zoom 1). Budget 30 ms, band edge 33; (1, 0) takes 50.686.
    //  - Without a zoom model, the 20.686 ms beyond the preview's 30 count as pixels (share
    //    0.408): (2, 1) is estimated at 23.2 ms and drawn at 35.9, over the band.
    //  - With the device's model only its 3.686 ms of pixels shrink with the zoom, and what
    //    neither model explains is taken as fixed (share 0.073, the device's own): (2, 1) is
    //    estimated at 35.9 (no fit) and (2, 2) at 27.9, as drawn, within the band.
    Device d;
    d.cost = ZoomCostModel{2.0, 4.0, 0.0};
    d.unseenMs = 15.0;
    auto firstChange = [&](const ZoomCostModel& model) {
        BudgetGovernor governor(budgetOf(30), {true, true}, ZoomControllerKind::Reactive, model);
        const Run run = drive(governor, d, 24);
        int over = 0;  // after the first two frames, which end the hold as a run over the band
        for (std::size_t f = 2; f < run.ms.size(); ++f) over += run.ms[f] > 33.0;
        return std::make_pair(run, over);
    };
    const auto [withModel, overWithModel] = firstChange(d.cost);
    CHECK(withModel.choices[1].zoom == 1);  // two frames at (1, 0), over the band
    CHECK(withModel.choices[2].zoom == 2);
    CHECK(withModel.choices[2].lodLevel == 2);
    CHECK(withModel.ms[2] == doctest::Approx(27.9216));
    CHECK(overWithModel == 0);
    const auto [without, overWithout] = firstChange(ZoomCostModel{});
    CHECK(without.choices[2].zoom == 2);
    CHECK(without.choices[2].lodLevel == 1);
    CHECK(without.ms[2] == doctest::Approx(35.9216));
    CHECK(overWithout == 2);  // until two frames over the band end the hold again
}

TEST_CASE("budget governor: reactive scales the last frame's fragments with the zoom's pixels") {
    // The undercount device with a fill-bound technique: 2 ms + 4 ms per million pixels + 10 ms
    // per million fragments, three fragments a pixel. Zoom parts: 33.334 ms at zoom 1, 9.834 at 2,
    // 5.485 at 3, 3.958 at 4; every level 15 ms more than previewed. (1, 0) takes 78.334 ms, over
    // twice a 30 ms budget: judged at once. The least loss that truly fits is zoom 4 at 16 px,
    // 28.958 ms (loss 1.5 + 0.6), ahead of zoom 3 at 32 px (26.485, loss 1.0 + 1.5). Taken with
    // the fragments of the frame drawn at zoom 1, scaled to each zoom, the estimates are exact.
    Device d;
    d.cost = ZoomCostModel{2.0, 4.0, 10.0};
    d.fragmentsPerPixel = 3.0;
    d.unseenMs = 15.0;
    BudgetGovernor governor(budgetOf(30), {true, true}, ZoomControllerKind::Reactive, d.cost);
    const Run run = drive(governor, d, 12);
    CHECK(run.ms[0] == doctest::Approx(78.3344));
    CHECK(run.choices[1].zoom == 4);
    CHECK(run.choices[1].lodLevel == 2);
    CHECK(run.ms[1] == doctest::Approx(28.9584));
    for (std::size_t f = 1; f < run.ms.size(); ++f) CHECK(run.ms[f] <= 33.0);
}

TEST_CASE("budget governor: reactive learns what LOD's pixels really cost from a change of zoom") {
    // The predictive test's device: the preview says 20 of level 0's 30 ms scale with pixels (12,
    // 6 and 3 of the others'), the device spends three times that (level 0 at zoom 1: 2 + 36.864
    // + 10 + 60 = 108.864 ms). With the device's zoom model, the first change of zoom alone shows
    // the factor: the frames drawn, less the model's pixels, less the preview's pixel part times
    // 3, leave exactly the preview's fixed part.
    Device d;
    d.lodPixelMs = {20.0, 12.0, 6.0, 3.0};
    d.lodPixelTruth = 3.0;
    d.lodMs = {30.0, 30.0, 30.0, 30.0};  // LOD saves nothing: the first change is the zoom's
    BudgetGovernor governor(budgetOf(90), {true, true}, ZoomControllerKind::Reactive, d.cost);
    CHECK(governor.lodPixelScale() == 1.0);
    const Run run = drive(governor, d, 12);
    REQUIRE(run.choices[2].zoom == 2);
    REQUIRE(run.choices[2].lodLevel == 0);
    CHECK(governor.lodPixelScale() == doctest::Approx(3.0));
    // The view never changes here, so the state's estimate stays what its frames took, through
    // the factor's change too: the views are compared at the factor as it stands.
    for (std::size_t f = 3; f < run.ms.size(); ++f) {
        CAPTURE(f);
        CHECK(run.choices[f].zoom == 2);
        CHECK(run.choices[f].predictedMs == doctest::Approx(run.ms[f]));
    }
}

TEST_CASE("budget governor: reactive acts on a load the LOD preview sees growing, before frames over the band") {
    // Settled at (1, 2), 48.864 ms under a 50 ms budget (band edge 55). Then the view turns into
    // a denser field: every LOD level costs 30 ms more (levels 60, 48, 40, 36), and over the next
    // two frames 5 ms more each.
    //  - Seen by LOD's preview, the reactive policy moves the measured time by the preview's
    //    growth at the current state, from the measured frames' views to the coming one. The
    //    turn: 78.864 ms at (1, 2), so it takes the least loss estimated to fit, (3, 2) at 46.099
    //    ms (loss 1.0 + 0.3), before drawing it. Then, one frame into the new state's hold, the
    //    views' growth (+10 against a median of +2.5) says 56.099, over the band: it steps again
    //    before drawing that frame (to (4, 3), 50.304 ms: nothing fits, the fastest), where
    //    waiting for two frames over the band drew 56.1 and then 61.1.
    //  - Unseen by the preview (the same loads as geometry it misses), it draws the turn at (1, 2)
    //    and waits for frames over the band, as before.
    auto turn = [](bool seen) {
        Device d;
        d.lodLossPx = {0.0, 0.1, 0.3, 1.0};
        BudgetGovernor governor(budgetOf(50), {true, true}, ZoomControllerKind::Reactive, d.cost);
        const Run settled = drive(governor, d, 20);
        REQUIRE(settled.choices.back().zoom == 1);
        REQUIRE(settled.choices.back().lodLevel == 2);
        Run run;
        for (int g = 0; g <= 6; ++g) {
            const double more = g == 0 ? 30.0 : g <= 2 ? 5.0 : 0.0;
            if (seen) {
                for (double& ms : d.lodMs) ms += more;
            } else {
                d.unseenMs += more;
            }
            const Run frame = drive(governor, d, 1);
            run.choices.push_back(frame.choices.front());
            run.ms.push_back(frame.ms.front());
        }
        return run;
    };
    const Run seen = turn(true);
    CHECK(seen.choices[0].zoom == 3);
    CHECK(seen.choices[0].lodLevel == 2);
    CHECK(seen.ms[0] == doctest::Approx(46.0989));
    CHECK(seen.choices[1].zoom == 3);  // +5: 51.099, within the band
    CHECK(seen.choices[1].lodLevel == 2);
    CHECK(seen.choices[2].zoom == 4);  // moved before drawing 56.099
    CHECK(seen.choices[2].lodLevel == 3);
    for (double ms : seen.ms) CHECK(ms <= 55.0);
    const Run unseen = turn(false);
    CHECK(unseen.choices[0].zoom == 1);
    CHECK(unseen.choices[0].lodLevel == 2);
    CHECK(unseen.ms[0] == doctest::Approx(78.864));
    CHECK(std::count_if(unseen.ms.begin(), unseen.ms.end(), [](double ms) { return ms > 55.0; }) >= 2);
}
