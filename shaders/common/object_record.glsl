// The object being drawn (common/object_records.h). The vertex stage takes its record as
// instanced attributes, places the vertex with its transform, and passes what the later stages
// use on as flat varyings (ObjectVarying; a geometry stage passes the block on). Flat varyings,
// not a storage buffer read per fragment, keep the fragment stages as cheap as with uniforms: on
// llvmpipe a read per fragment made a blending pass 6x slower.
//
// The per-object values keep the names they had as uniforms, so every technique's stages read
// them as before: uObjectId, uVolumeEntry (oit/volume/volume_store.glsl) and uVolumeFilter
// (common/shade_material.glsl).
// A stand-in's fragment stage also needs the normal matrix (common/scene_main.glsl): its build
// passes that on too.
//
// The vertex stage defines STRATA_OBJECT_VERTEX_STAGE before including this; the fragment stages
// include it as it is. A geometry stage (oit/screendoor/object_mask.geom.glsl) defines
// STRATA_OBJECT_GEOMETRY_STAGE, declares the block in and out with STRATA_OBJECT_VARYING_MEMBERS
// and copies it.
#ifndef STRATA_OBJECT_RECORD_GLSL
#define STRATA_OBJECT_RECORD_GLSL
#include "bindings.h"
#include "common/object_records.h"

// The members of ObjectVarying, the block every stage declares with them.
#ifdef STRATA_IMPOSTOR
#define STRATA_OBJECT_VARYING_MEMBERS flat uint id; flat int volumeEntry; flat vec3 volumeFilter; flat mat3 normalMatrix;
#else
#define STRATA_OBJECT_VARYING_MEMBERS flat uint id; flat int volumeEntry; flat vec3 volumeFilter;
#endif

#if defined(STRATA_OBJECT_VERTEX_STAGE)
// Instanced attributes: one record per instance (GpuScene's object records), or for a vertex
// array without them (a stand-in's, uploadMesh's alone) the current generic values.
layout(location = ATTRIB_OBJECT) in uvec2 inObject;  // id, volume entry
layout(location = ATTRIB_OBJECT_MODEL) in mat4 inModel;
layout(location = ATTRIB_OBJECT_FILTER) in vec3 inVolumeFilter;

out ObjectVarying { STRATA_OBJECT_VARYING_MEMBERS } vObject;

// The normal matrix, the inverse transpose of the model's linear part: computed per vertex, which
// costs llvmpipe less than fetching three more attributes.
mat3 objectNormalMatrix() {
    return transpose(inverse(mat3(inModel)));
}
// Writes ObjectVarying; the vertex stage calls it once.
void passObjectOn(mat3 normalMatrix) {
    vObject.id = inObject.x;
    vObject.volumeEntry = int(inObject.y);
    vObject.volumeFilter = inVolumeFilter;
#ifdef STRATA_IMPOSTOR
    vObject.normalMatrix = normalMatrix;
#endif
}

#elif !defined(STRATA_OBJECT_GEOMETRY_STAGE)
in ObjectVarying { STRATA_OBJECT_VARYING_MEMBERS } vObject;
#define uObjectId (vObject.id)
#define uVolumeEntry (vObject.volumeEntry)
#define uVolumeFilter (vObject.volumeFilter)
#ifdef STRATA_IMPOSTOR
#define uNormalMatrix (vObject.normalMatrix)
#endif
#endif

#endif
