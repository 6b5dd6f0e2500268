// What a scene program takes per object (render/object_records.hpp), shared by C++ and GLSL: the
// vertex stage reads it as instanced vertex attributes (divisor 1) from a buffer of these
// records, so instance i of a draw is record (base instance + i), and one instanced draw draws
// many objects that share a mesh and a material, each with its own transform, id and volume
// values (common/object_record.glsl). The material stays in uniforms, set once per draw: a batch
// shares it.
// Why attributes and not a storage buffer indexed in the shader: llvmpipe fetches an instanced
// attribute once per instance and loads a storage buffer once per vertex; the storage buffer made
// a vertex-bound pass (orchard:1000, 2.2 M triangles) 2.7x slower, the attributes do not.
// Scalars only, so C++ and GLSL agree on the offsets (common/host_device.h).
#ifndef STRATA_OBJECT_RECORDS_H
#define STRATA_OBJECT_RECORDS_H
#include "common/host_device.h"

GPU_NAMESPACE_BEGIN

// One object: its world transform, the id the techniques store, which faces enter its volume
// (render/gpu_scene.cpp's volume entry) and what its medium lets through where the view enters
// it (the transmission build's filter).
struct ObjectRecord {
    float model[16];        // column-major: attributes ATTRIB_OBJECT_MODEL .. +3, a column each
    uint objectId;          // ATTRIB_OBJECT.x
    int volumeEntry;        // ATTRIB_OBJECT.y: 0 a thin surface; +1 / -1 which faces enter the volume
    float volumeFilter[3];  // ATTRIB_OBJECT_FILTER: exp(-tau x thickness) through the medium, per channel
};

// Vertex attribute locations of the record (common/bindings.h has the mesh's, 0 .. 6).
GPU_CONST uint ATTRIB_OBJECT = 7u;         // uvec2: objectId, volumeEntry (its bits)
GPU_CONST uint ATTRIB_OBJECT_MODEL = 8u;   // mat4: 8, 9, 10, 11
GPU_CONST uint ATTRIB_OBJECT_FILTER = 12u; // vec3

GPU_NAMESPACE_END

#endif
