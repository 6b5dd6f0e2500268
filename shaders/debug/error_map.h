// What the error map's host code (core/render/error_map.cpp) and its compute pass
// (debug/error_map.comp.glsl) agree on: where the two images, the false colour and the
// per-group partial sums go, and the layout of one partial.
#ifndef STRATA_ERROR_MAP_H
#define STRATA_ERROR_MAP_H
#include "common/host_device.h"

// The false colour of an error e (the largest per-channel difference) at t = e / scale: six stops,
// dark blue (t -> 0) through blue, cyan, green, yellow to red (t >= 1), linear RGB, three floats
// each; a pixel with e == 0 shows the reference's luminance L as ERROR_SAME_BASE +
// ERROR_SAME_GAIN * L. The GPU pass and the CPU copy for reports (errorMapImage) both read these.
#define ERROR_RAMP_STOPS 0.02, 0.02, 0.25, 0.05, 0.2, 0.9, 0.0, 0.75, 0.85, \
                         0.1, 0.8, 0.15, 0.95, 0.85, 0.05, 0.95, 0.05, 0.03
#define ERROR_SAME_BASE 0.03
#define ERROR_SAME_GAIN 0.22

GPU_NAMESPACE_BEGIN

GPU_CONST uint BIND_ERROR_IMAGE = 0u;      // texture unit: the image under test (RGBA32F, linear)
GPU_CONST uint BIND_ERROR_REFERENCE = 1u;  // texture unit: the reference of the same frame
// The false colour goes to BIND_RESOLVE_OUTPUT (common/bindings.h), rgba32f.
GPU_CONST uint BIND_ERROR_PARTIALS = 2u;   // SSBO: one ErrorPartial per work group

// Work groups are ERROR_GROUP_SIZE pixels a side; the host rounds the dispatch up.
GPU_CONST uint ERROR_GROUP_SIZE = 8u;

// One work group's share: the sum of squared RGB differences over its pixels (at most 64 pixels
// of 3 channels, so a float sum loses nothing the RMSE shows; the host adds groups in double),
// its largest per-channel difference and the pixel (y * width + x) that holds it, the lowest
// index among equal maxima so the result does not depend on scheduling.
struct ErrorPartial {
    float sumSquares;
    float maxError;
    uint maxPixel;
    uint pad;
};

GPU_NAMESPACE_END

#endif
