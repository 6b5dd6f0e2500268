#pragma once
// The per-object values every scene program takes (shaders/common/object_records.h): transform,
// id and volume values, packed from a scene once. A scene's vertex arrays read them as instanced
// attributes from a buffer of records, so one instanced draw draws many objects
// (render/gpu_scene.hpp's drawObjects) with no uniform call per object. A stand-in's quads get
// them on their first draw (readsObjectRecords); a vertex array without them (a mesh uploaded
// alone, the LOD calibration's) takes the current generic values instead.
#include "common/object_records.h"

#include <epoxy/gl.h>
#include <glm/glm.hpp>

namespace strata {

// One object's record: `world`, the id, and the volume values.
gpu::ObjectRecord makeObjectRecord(const glm::mat4& world, unsigned objectId, int volumeEntry = 0,
                                   const glm::vec3& volumeFilter = glm::vec3(1.0f));

// Makes `vertexArray` read the record attributes, one record per instance, from `records` (a
// buffer of gpu::ObjectRecord): instance i of a draw with base instance b reads record b + i.
void attachObjectRecords(GLuint vertexArray, GLuint records);

// Whether `vertexArray` reads its records from `records` (attachObjectRecords was called on it
// with that buffer); false for a new vertex array, or one whose name was reused.
bool readsObjectRecords(GLuint vertexArray, GLuint records);

// Sets the generic values of the record attributes: what a draw from a vertex array without them
// takes for every vertex.
void setCurrentObject(const gpu::ObjectRecord& record);

}  // namespace strata
