#pragma once
// The panel's "View" section: the view selector and, for the coplanarity heatmap, Fig. 13's
// legend with each colour's share of the pixels, C_p and the R_h of one-fragment-per-layer peeling.
#include "view_kind.hpp"

#include "render/coplanarity.hpp"

namespace strata {

// `stats`: the last frame's detector figures (null when the heatmap was not computed);
// `detectorMs`: the detector's GPU time on that frame.
void drawViewSection(ViewKind& view, const CoplanarityStats* stats, double detectorMs);

}  // namespace strata
