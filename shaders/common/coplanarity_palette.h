// The coplanarity heatmap's colours, Fig. 13 of Vasilakis and Fudos, "Depth-fighting aware methods
// for multi-fragment rendering": written once here for the C++ heatmap (core/render/coplanarity.*)
// and the GPU detector (shaders/oit/coplanarity_detect.comp.glsl), so the two cannot drift.
// Entry i colours a pixel whose largest depth layer holds i + 1 fragments; entry 0 also takes
// pixels with no fragment at all, and the last entry every layer of 9 or more.
// Values are the CSS/X11 named colours as sRGB 0xRRGGBB; both sides decode them to linear RGB.
#ifndef STRATA_COPLANARITY_PALETTE_H
#define STRATA_COPLANARITY_PALETTE_H
#include "common/host_device.h"

//                               grey      red       blue      green     cyan
#define COPLANARITY_PALETTE_SRGB 0x808080u, 0xFF0000u, 0x0000FFu, 0x008000u, 0x00FFFFu, \
                                 0x7FFFD4u, 0xFF00FFu, 0xFFFF00u, 0xA52A2Au
//                               aquamarine fuchsia  yellow    brown (9 or more)

GPU_NAMESPACE_BEGIN

GPU_CONST uint COPLANARITY_PALETTE_SIZE = 9u;

GPU_NAMESPACE_END

#endif
