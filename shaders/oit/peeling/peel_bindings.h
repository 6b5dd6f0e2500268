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
// dual with atomic_range: image units (r32i) where a peel pass leaves the next range's nearest
// and farthest depth bits (dual_peel.frag.glsl, dual_range_pack.frag.glsl).
GPU_CONST uint BIND_DUAL_NEXT_NEAREST = 0u;
GPU_CONST uint BIND_DUAL_NEXT_FARTHEST = 1u;
// Their empty values: below and above every depth's bits (dual_range_images.glsl).
GPU_CONST int DUAL_NO_NEAREST = -1;
GPU_CONST int DUAL_NO_FARTHEST = 0x7fffffff;
// f2b's and dual's STRATA_RGB_TRANSMITTANCE builds: what the (front) layer, the (front)
// accumulation, and dual's back layer and back accumulation let through per channel (units the
// coplanarity variants below use for their own targets).
GPU_CONST uint BIND_PEEL_LAYER_FILTER = 7u;
GPU_CONST uint BIND_PEEL_ACCUM_FILTER = 8u;
GPU_CONST uint BIND_PEEL_BACK_FILTER = 9u;
GPU_CONST uint BIND_PEEL_BACK_ACCUM_FILTER = 10u;

// The coplanarity-aware variants (f2b-2p, f2b-3p, dual-2p; coplanar_layer.glsl). Front side
// units; dual-2p's back side uses the same unit + BIND_COPLANAR_BACK_OFFSET.
GPU_CONST uint BIND_COPLANAR_STATE = 7u;       // (layer anchor depth, id low, id high, 0) per pixel
GPU_CONST uint BIND_COPLANAR_COUNT = 8u;       // (-id min, id max, next anchor, count) of the layer
GPU_CONST uint BIND_COPLANAR_MIN_COLOR = 9u;   // colour of the id-min fragment (f2b-2p, dual-2p: the sum first)
GPU_CONST uint BIND_COPLANAR_MAX_COLOR = 10u;  // colour of the id-max fragment
GPU_CONST uint BIND_COPLANAR_LAYER = 11u;      // the open layer's far part (premultiplied colour, transmittance)
GPU_CONST uint BIND_COPLANAR_ACCUM = 12u;      // accumulated (premultiplied colour, transmittance)
GPU_CONST uint BIND_COPLANAR_NEXT_DEPTH = 13u; // f2b-3p: the depth pass's nearest fragment beyond the layer
// Their STRATA_RGB_TRANSMITTANCE builds' second texels (coplanar_layer.glsl), above the material
// textures (common/bindings.h: 20 .. 25).
GPU_CONST uint BIND_COPLANAR_MIN_OPACITY = 26u;   // the id-min fragment's opacity per channel
GPU_CONST uint BIND_COPLANAR_MAX_OPACITY = 27u;   // the id-max fragment's
GPU_CONST uint BIND_COPLANAR_LAYER_PASSES = 28u;  // what the open layer's far part lets through
GPU_CONST uint BIND_COPLANAR_ACCUM_PASSES = 29u;  // what the accumulation lets through
GPU_CONST uint BIND_COPLANAR_BACK_OFFSET = 7u; // dual-2p back side: 14 .. 19, and 33 .. 36
GPU_CONST uint BIND_COPLANAR_ID_BASE = 2u;     // SSBO: first id of each object (coplanar_ids.hpp)

GPU_NAMESPACE_END

#endif
