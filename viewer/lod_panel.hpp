#pragma once
// The panel's "Level of detail" section (lod/lod_controller.hpp): the toggle that forces all
// geometry or all impostors or leaves the choice to the cost model, the error bound, and which
// objects are impostors with their memory, view error and predicted costs. printLodFigures is
// its terminal twin for smoke tests and logs.
#include "lod/lod_controller.hpp"

namespace strata {

// `budgetBoundPx` > 0: the frame budget sets auto's error bound (zoom_driver.hpp), so the panel
// shows it instead of the slider.
void drawLodSection(lod::LodController& lod, double budgetBoundPx = 0.0);
void printLodFigures(const lod::LodController& lod);

}  // namespace strata
