#include "oit/peeling/coplanar_ids.hpp"

#include "oit/peeling/peel_bindings.h"

#include <algorithm>
#include <vector>

namespace strata::peeling {

bool CoplanarIds::bind(const FrameContext& frame) {
    const auto& objects = frame.scene.objects();
    std::vector<GLuint> base(std::max<std::size_t>(objects.size(), 1), 0);
    std::uint64_t next = 0;
    for (std::size_t o = 0; o < objects.size(); ++o) {
        base[o] = GLuint(std::min<std::uint64_t>(next, 0xFFFFFFFFu));
        std::uint64_t primitives = frame.scene.scene().meshes[std::size_t(objects[o].mesh)].triangleCount();
        // A stand-in's primitive ids run over its slice quads' triangles (from 0 in each draw of
        // its multi-draw, so their sum bounds them): the range must hold those instead.
        if (const StandInDraw* standIn = frame.standInOf(int(o))) {
            std::uint64_t quadTriangles = 0;
            for (GLsizei count : standIn->count) quadTriangles += std::uint64_t(count) / 3;
            primitives = std::max(primitives, quadTriangles);
        }
        next += primitives;
    }
    const std::size_t bytes = base.size() * sizeof(GLuint);
    if (bytes > capacity_) {
        buffer_ = gl::Buffer::create();
        glNamedBufferStorage(buffer_.id(), GLsizeiptr(bytes), nullptr, GL_DYNAMIC_STORAGE_BIT);
        capacity_ = bytes;
    }
    glNamedBufferSubData(buffer_.id(), 0, GLsizeiptr(bytes), base.data());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BIND_COPLANAR_ID_BASE, buffer_.id());
    // Ids are stored as the bits of positive normal floats: rank + 2^23 below 0x7F800000 (inf).
    return next < 0x7F800000u - 0x00800000u;
}

}  // namespace strata::peeling
