// Texture units the peeling family uses beyond the shared ones (common/bindings.h owns 0 and 1).
#ifndef STRATA_PEEL_BINDINGS_H
#define STRATA_PEEL_BINDINGS_H
#include "common/host_device.h"

GPU_NAMESPACE_BEGIN

GPU_CONST uint BIND_PEEL_PREVIOUS = 2u;    // last peeled depth (f2b) or min-max depth (dual, bun range)
GPU_CONST uint BIND_PEEL_LAYER = 3u;       // colour of the layer just peeled / front layer / bucket depths
GPU_CONST uint BIND_PEEL_BACK = 4u;        // dual: back layer
GPU_CONST uint BIND_PEEL_ACCUM = 5u;       // accumulated (colour, transmittance)
GPU_CONST uint BIND_PEEL_BACK_ACCUM = 6u;  // dual: back accumulation
GPU_CONST uint BIND_BUCKET_COLORS = 1u;    // bun: image unit of the per-slot colours

GPU_NAMESPACE_END

#endif
