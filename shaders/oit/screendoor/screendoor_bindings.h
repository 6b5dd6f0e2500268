// Binding points private to the screen-door family, apart from common/bindings.h because
// nothing outside the family reads them; texture units 0 and 1 stay the shared opaque colour
// and depth (the supersampled fill reads both).
#ifndef STRATA_SCREENDOOR_BINDINGS_H
#define STRATA_SCREENDOOR_BINDINGS_H
#include "common/host_device.h"

GPU_NAMESPACE_BEGIN

GPU_CONST uint BIND_ALPHA_MASKS = 2u;        // texture unit: one binary mask per alpha level (r8ui array)
GPU_CONST uint BIND_DOWNSAMPLE_SOURCE = 3u;  // texture unit: the supersampled level a 2x2 average reads

// screendoor-object-sw: the point samples (ScreenDoorPoint), the mesh it samples and the
// object colours the points are shaded with (SSBOs; 1 stays the A-buffer's node pool), and the
// counters (BIND_COUNTERS): points wanted, triangles whose sample count was bounded.
GPU_CONST uint BIND_POINTS = 2u;
GPU_CONST uint BIND_MESH_VERTICES = 3u;
GPU_CONST uint BIND_MESH_INDICES = 4u;
GPU_CONST uint BIND_OBJECT_COLORS = 5u;
GPU_CONST uint BIND_MESH_ATTRIBUTES = 6u;  // the mesh's TEXCOORD_n and COLOR_0 arrays (render/gpu_scene.hpp)
GPU_CONST uint POINT_SAMPLES_GROUP_SIZE = 64u;  // triangles per compute group
GPU_CONST uint POINT_CHUNK = 16384u;            // lattice points one invocation walks

// One point sample (a kept surface sample of screendoor-object-sw), scalars only so C++ and
// std430 pack it alike: world position, the world normal packed as snorm 4x8, the object id,
// and what its base colour texture and COLOR_0 make of the factor colour there (half r, g and
// half b, 0; 1 where the material has neither).
struct ScreenDoorPoint {
    float x;
    float y;
    float z;
    uint normal;
    uint object;
    uint tintRG;
    uint tintB;
};

// Alpha is quantized to this many levels above zero (8-bit alpha); mask layer l keeps a texel
// with probability l / ALPHA_LEVELS, so layer 0 is empty and the last layer is full.
GPU_CONST uint ALPHA_LEVELS = 255u;

GPU_NAMESPACE_END

#endif
