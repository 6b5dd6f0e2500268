#include "render/stand_in.hpp"

#include <tuple>

namespace strata {

gl::VertexArray makeStandInVertexArray(GLuint buffer) {
    gl::VertexArray array = gl::VertexArray::create();
    const GLuint vao = array.id();
    glVertexArrayVertexBuffer(vao, 0, buffer, 0, kStandInFloatsPerVertex * sizeof(float));
    glEnableVertexArrayAttrib(vao, 0);
    glEnableVertexArrayAttrib(vao, 2);
    glVertexArrayAttribFormat(vao, 0, 3, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribFormat(vao, 2, 4, GL_FLOAT, GL_FALSE, 3 * sizeof(float));
    glVertexArrayAttribBinding(vao, 0, 0);
    glVertexArrayAttribBinding(vao, 2, 0);
    return array;
}

namespace {

auto drawKey(const StandInDraw& d) {
    return std::tie(d.vertexArray, d.atlas, d.albedo, d.slices, d.overlap, d.first, d.count);
}

}  // namespace

bool sameStandInDraw(const StandInDraw& a, const StandInDraw& b) { return drawKey(a) == drawKey(b); }

bool standInDrawBefore(const StandInDraw& a, const StandInDraw& b) { return drawKey(a) < drawKey(b); }

}  // namespace strata
