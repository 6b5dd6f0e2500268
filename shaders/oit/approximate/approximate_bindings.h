// Binding points private to the approximate family, apart from common/bindings.h because
// nothing outside the family reads them; texture unit 0 stays the shared opaque colour.
#ifndef STRATA_APPROXIMATE_BINDINGS_H
#define STRATA_APPROXIMATE_BINDINGS_H
#include "common/host_device.h"

GPU_NAMESPACE_BEGIN

GPU_CONST uint BIND_SAMPLE_DEPTHS = 0u;  // image unit: stochastic per-sample depth bits (r32ui array)
GPU_CONST uint BIND_ACCUM = 2u;          // texture unit: accumulation (RGBA32F)
GPU_CONST uint BIND_TRANSMITTANCE = 3u;  // texture unit: revealage / total transmittance (R16F, R32F)

GPU_NAMESPACE_END

#endif
