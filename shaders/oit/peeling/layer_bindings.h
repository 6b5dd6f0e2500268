// Texture units of the front-to-back layer variants' anchors (f2b-ll, f2b-fab, f2b-kb), beyond
// the shared ones (common/bindings.h) and the peeling family's (peel_bindings.h).
#ifndef STRATA_LAYER_BINDINGS_H
#define STRATA_LAYER_BINDINGS_H
#include "common/host_device.h"

GPU_NAMESPACE_BEGIN

// The layer anchor, RGBA32UI: its colour as packHalf2x16 (r, g) and (b, alpha), the layout of
// stored fragments, then object id + 1 (0: no anchor) and primitive id.
GPU_CONST uint BIND_ANCHOR = 4u;

GPU_NAMESPACE_END

#endif
