// What the coplanarity detector's host code (core/oit/coplanarity_detector.cpp) and its resolve
// (coplanarity_detect.comp.glsl) agree on. The store pass is the A-buffer's (BIND_HEADS,
// BIND_NODES, BIND_COUNTERS of common/bindings.h); these sit beside those in one program.
#ifndef STRATA_COPLANARITY_BINDINGS_H
#define STRATA_COPLANARITY_BINDINGS_H
#include "common/host_device.h"

GPU_NAMESPACE_BEGIN

GPU_CONST uint BIND_LARGEST_LAYER = 1u;       // image unit: per pixel largest layer, fragments (rg32ui)
GPU_CONST uint BIND_COPLANARITY_TOTALS = 2u;  // SSBO: uint totals[COPLANARITY_TOTALS], see below
// The heatmap colour goes to BIND_RESOLVE_OUTPUT (rgba16f here).

// totals[0 .. COPLANARITY_BINS - 1]: pixels whose largest layer holds that many fragments
// (bin 0: no fragment; the last bin: that many or more); then the number of depth layers summed
// over every pixel (what front-to-back peeling can capture: one fragment per layer).
GPU_CONST uint COPLANARITY_BINS = 10u;
GPU_CONST uint COPLANARITY_TOTAL_LAYERS = COPLANARITY_BINS;
GPU_CONST uint COPLANARITY_TOTALS = COPLANARITY_BINS + 1u;

GPU_NAMESPACE_END

#endif
