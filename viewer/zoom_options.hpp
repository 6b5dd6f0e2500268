#pragma once
// The zoom-rendering options, described once for `render`, `bench` and `view`: a fixed
// `--zoom Z [--zoom-blur]`, and for bench and view `--frame-budget-ms T` with
// `--zoom-controller reactive|predictive`, `--zoom-max Z` and `--budget-levers zoom|lod|zoom,lod` (which need the budget, and which a
// fixed zoom excludes).
#include "frame/budget_governor.hpp"
#include "frame/zoom_controller.hpp"
#include "lod/lod_select.hpp"
#include "render/deflection_warp.hpp"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace strata {

struct ZoomArgs {
    std::string zoom = "1";
    bool blur = false;
    double budgetMs = 0.0;               // 0: no budget, the zoom is fixed
    std::string controller = "reactive";
    int maxZoom = 8;
    std::string leverList = "zoom,lod";  // --budget-levers: what the budget steers (frame/budget_governor.hpp)

    int fixedZoom() const;               // parseZoom (render/zoom.hpp): throws naming the text
    DeflectFilter filter() const { return blur ? DeflectFilter::Bilinear : DeflectFilter::Nearest; }
    std::optional<ZoomBudget> budget() const;
    ZoomControllerKind controllerKind() const { return parseZoomController(controller); }
    // The levers for a LOD mode: the LOD bound is a lever of auto only. Asked for alone with
    // another mode, throws naming --lod; with the zoom, the zoom steers alone.
    BudgetLevers levers(lod::LodMode mode) const;
};

// `what` names the image the zoom divides ("size", "window") in the help text.
void addZoomOptions(CLI::App* cmd, ZoomArgs& args, bool withBudget, const std::string& what);

}  // namespace strata
