#pragma once
// TEMPORARY copy of the lead's core/render/stand_in.hpp (lod-contract.md), so lod/ compiles
// before the stand-ins commit lands on main; deleted at that merge.
#include <epoxy/gl.h>

#include <vector>

namespace strata {

// What a pass draws in an object's place for one frame (a layered impostor's slices, lod/).
struct StandInDraw {
    GLuint vertexArray = 0;
    GLuint atlas = 0;
    int slices = 1;
    float overlap = 0.0f;
    std::vector<GLint> first;
    std::vector<GLsizei> count;
};

}  // namespace strata
