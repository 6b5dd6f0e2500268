// The volumetric resolve's interface (ll-volume, abuffer-volume), shared by C++ and GLSL:
// bindings, the per-object medium table and the flags the store passes put on a node.
#ifndef STRATA_VOLUME_BINDINGS_H
#define STRATA_VOLUME_BINDINGS_H
#include "common/host_device.h"

GPU_NAMESPACE_BEGIN

// Texture unit: the medium table (one VolumeObject per object id) as an RGB32F buffer texture,
// two texels an object (tau, then scatter). A texel fetch, not a storage-buffer read: llvmpipe
// loads a storage buffer lane by lane, which cost a quarter of the volumetric resolve.
GPU_CONST uint BIND_VOLUME_MEDIA = 4u;
GPU_CONST uint BIND_VOLUME_STATS = 7u;    // SSBO: uint counters the resolve reports through

// How many volumes may overlap at one point of a ray. Deeper nesting is counted (and the
// extra volumes ignored), never silently wrong.
GPU_CONST uint VOLUME_MAX_NESTED = 8u;

// A node's primitiveId carries two flags above the primitive (a mesh has fewer than 2^30
// triangles; the loaders and GpuScene check): the fragment bounds a volume, and it enters it.
GPU_CONST uint VOLUME_FLAG_MEDIUM = 0x80000000u;
GPU_CONST uint VOLUME_FLAG_ENTRY = 0x40000000u;
GPU_CONST uint VOLUME_PRIMITIVE_MASK = 0x3FFFFFFFu;

// One object's medium: attenuation tau per metre and tau * albedo (the scattering
// coefficient), per channel. Scalars only, so C++ and std430 lay it out alike.
struct VolumeObject {
    float tauR, tauG, tauB;
    float scatterR, scatterG, scatterB;
};

// Counters in the BIND_VOLUME_STATS buffer.
GPU_CONST uint VOLUME_STAT_NESTING_OVERFLOW = 0u;  // fragments of volumes past VOLUME_MAX_NESTED
GPU_CONST uint VOLUME_STAT_COUNT = 1u;

GPU_NAMESPACE_END

#endif
