#pragma once
// `abuffer`, the exact reference: every transparent fragment in front of the opaque depth goes
// into a per-pixel linked list, each list is sorted by (depth, object id, primitive id) and
// composited. Memory is grown to the counted fragments and the frame re-rendered until nothing
// overflows; where the fragments exceed the largest storage block the device allows, the frame
// is rendered in screen tiles, each within the limit. Nothing is ever dropped silently.
#include "oit/technique.hpp"

namespace strata {

TechniqueEntry abufferEntry();

}  // namespace strata
