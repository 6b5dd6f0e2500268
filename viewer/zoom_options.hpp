#pragma once
// The zoom-rendering options, described once for `render`, `bench` and `view`: a fixed
// `--zoom Z [--zoom-blur]`, and for bench and view `--frame-budget-ms T` with
// `--zoom-controller reactive|predictive` and `--zoom-max Z` (which need the budget, and which a
// fixed zoom excludes).
#include "frame/zoom_controller.hpp"
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

    int fixedZoom() const;               // parseZoom (render/zoom.hpp): throws naming the text
    DeflectFilter filter() const { return blur ? DeflectFilter::Bilinear : DeflectFilter::Nearest; }
    std::optional<ZoomBudget> budget() const;
    ZoomControllerKind controllerKind() const { return parseZoomController(controller); }
};

// `what` names the image the zoom divides ("size", "window") in the help text.
void addZoomOptions(CLI::App* cmd, ZoomArgs& args, bool withBudget, const std::string& what);

}  // namespace strata
