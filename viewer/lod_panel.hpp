#pragma once
// The panel's "Level of detail" section (lod/lod_controller.hpp): the toggle that forces all
// geometry or all impostors or leaves the choice to the cost model, the error bound, and which
// objects are impostors with their memory, view error and predicted costs. printLodFigures is
// its terminal twin for smoke tests and logs.
#include "lod/lod_controller.hpp"

namespace strata {

void drawLodSection(lod::LodController& lod);
void printLodFigures(const lod::LodController& lod);

}  // namespace strata
