// Binding points of lod/'s own programs (the bake and the hole-filling id render). The draw of
// impostors in scene passes uses common/bindings.h's BIND_IMPOSTOR_ATLAS instead.
#ifndef STRATA_LOD_BINDINGS_H
#define STRATA_LOD_BINDINGS_H
#include "common/host_device.h"

GPU_NAMESPACE_BEGIN

GPU_CONST uint BIND_BAKE_PREVIOUS_DEPTH = 0u;  // texture unit: the previous peel's depth (bake)
GPU_CONST uint BIND_SLICE_ATLAS = 1u;          // texture unit: the atlas the id render tests

// Depth codes in the atlas's alpha: 0 empty, 1..255 the stored surface's t in 255 bins.
GPU_CONST uint IMPOSTOR_DEPTH_CODES = 255u;

GPU_NAMESPACE_END

#endif
