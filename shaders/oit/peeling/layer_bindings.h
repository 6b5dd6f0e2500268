// Texture units of the front-to-back layer variants' anchors (f2b-ll, f2b-fab, f2b-kb), beyond
// the shared ones (common/bindings.h) and the peeling family's (peel_bindings.h).
#ifndef STRATA_LAYER_BINDINGS_H
#define STRATA_LAYER_BINDINGS_H
#include "common/host_device.h"

GPU_NAMESPACE_BEGIN

GPU_CONST uint BIND_ANCHOR_IDS = 4u;    // the layer anchor's (object id + 1, primitive id), RG32UI; 0: none
GPU_CONST uint BIND_ANCHOR_COLOR = 5u;  // the layer anchor's colour (resolve)

GPU_NAMESPACE_END

#endif
