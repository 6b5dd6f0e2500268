#include "render/object_records.hpp"

#include <cstddef>
#include <cstring>

namespace strata {
namespace {

// The vertex buffer binding point the record attributes read from (the mesh's attributes use the
// points of their own locations, 0 .. 6).
constexpr GLuint kRecordBinding = gpu::ATTRIB_OBJECT;

}  // namespace

gpu::ObjectRecord makeObjectRecord(const glm::mat4& world, unsigned objectId, int volumeEntry,
                                   const glm::vec3& volumeFilter) {
    gpu::ObjectRecord r{};
    std::memcpy(r.model, &world[0][0], sizeof r.model);
    r.objectId = objectId;
    r.volumeEntry = volumeEntry;
    r.volumeFilter[0] = volumeFilter.x;
    r.volumeFilter[1] = volumeFilter.y;
    r.volumeFilter[2] = volumeFilter.z;
    return r;
}

void attachObjectRecords(GLuint vao, GLuint records) {
    auto attach = [&](GLuint location) {
        glEnableVertexArrayAttrib(vao, location);
        glVertexArrayAttribBinding(vao, location, kRecordBinding);
    };
    attach(gpu::ATTRIB_OBJECT);
    // objectId and volumeEntry, adjacent: read as a uvec2 (the shader takes the entry's bits back).
    glVertexArrayAttribIFormat(vao, gpu::ATTRIB_OBJECT, 2, GL_UNSIGNED_INT, GLuint(offsetof(gpu::ObjectRecord, objectId)));
    for (GLuint column = 0; column < 4; ++column) {
        attach(gpu::ATTRIB_OBJECT_MODEL + column);
        glVertexArrayAttribFormat(vao, gpu::ATTRIB_OBJECT_MODEL + column, 4, GL_FLOAT, GL_FALSE,
                                  GLuint(offsetof(gpu::ObjectRecord, model) + column * 4 * sizeof(float)));
    }
    attach(gpu::ATTRIB_OBJECT_FILTER);
    glVertexArrayAttribFormat(vao, gpu::ATTRIB_OBJECT_FILTER, 3, GL_FLOAT, GL_FALSE,
                              GLuint(offsetof(gpu::ObjectRecord, volumeFilter)));
    glVertexArrayVertexBuffer(vao, kRecordBinding, records, 0, sizeof(gpu::ObjectRecord));
    glVertexArrayBindingDivisor(vao, kRecordBinding, 1);
}

bool readsObjectRecords(GLuint vao, GLuint records) {
    GLint buffer = 0, enabled = 0;
    glGetVertexArrayIndexediv(vao, kRecordBinding, GL_VERTEX_BINDING_BUFFER, &buffer);
    glGetVertexArrayIndexediv(vao, gpu::ATTRIB_OBJECT_MODEL, GL_VERTEX_ATTRIB_ARRAY_ENABLED, &enabled);
    return enabled && GLuint(buffer) == records;
}

void setCurrentObject(const gpu::ObjectRecord& r) {
    GLuint entry = 0;
    std::memcpy(&entry, &r.volumeEntry, sizeof entry);
    glVertexAttribI4ui(gpu::ATTRIB_OBJECT, r.objectId, entry, 0u, 1u);
    for (GLuint column = 0; column < 4; ++column) glVertexAttrib4fv(gpu::ATTRIB_OBJECT_MODEL + column, r.model + 4 * column);
    glVertexAttrib3fv(gpu::ATTRIB_OBJECT_FILTER, r.volumeFilter);
}

}  // namespace strata
