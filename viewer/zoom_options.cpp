#include "zoom_options.hpp"

#include "render/zoom.hpp"

namespace strata {

int ZoomArgs::fixedZoom() const { return parseZoom(zoom); }

std::optional<ZoomBudget> ZoomArgs::budget() const {
    if (budgetMs <= 0.0) return std::nullopt;
    ZoomBudget b;
    b.targetMs = budgetMs;
    b.maxZoom = maxZoom;
    return b;
}

BudgetLevers ZoomArgs::levers(lod::LodMode mode) const {
    BudgetLevers l = parseBudgetLevers(leverList);
    if (mode == lod::LodMode::Auto || !l.lod) return l;
    if (!l.zoom)
        throw std::invalid_argument("--budget-levers lod needs --lod auto (the bound steers auto's choice; --lod is " +
                                    std::string(lod::to_string(mode)) + ")");
    return {true, false};
}

void addZoomOptions(CLI::App* cmd, ZoomArgs& args, bool withBudget, const std::string& what) {
    auto* zoom = cmd->add_option("--zoom", args.zoom, "draw at 1/Z of the " + what + " and enlarge (1..16)")
                     ->capture_default_str();
    cmd->add_flag("--zoom-blur", args.blur, "enlarge with a bilinear blur instead of pixel replication");
    if (!withBudget) return;
    auto* budget = cmd->add_option("--frame-budget-ms", args.budgetMs,
                                   "pick the zoom per frame for this frame time (with --zoom-controller)")
                       ->check(CLI::Range(0.001, 1e6));
    budget->excludes(zoom);
    cmd->add_option("--zoom-controller", args.controller, "reactive or predictive (with --frame-budget-ms)")
        ->check(CLI::IsMember({"reactive", "predictive"}))
        ->capture_default_str()
        ->needs(budget);
    cmd->add_option("--budget-levers", args.leverList,
                    "what the budget steers: zoom, lod (the auto LOD error bound) or zoom,lod")
        ->check([](const std::string& text) {
            try {
                parseBudgetLevers(text);
                return std::string();
            } catch (const std::invalid_argument& e) {
                return std::string(e.what());
            }
        })
        ->capture_default_str()
        ->needs(budget);
    cmd->add_option("--zoom-max", args.maxZoom, "the largest zoom a controller may pick")
        ->check(CLI::Range(1, 16))
        ->capture_default_str()
        ->needs(budget);
}

}  // namespace strata
