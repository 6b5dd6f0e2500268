#pragma once
// What a pass draws in an object's place for one frame: a layered impostor's slice quads
// (lod/layered_impostor.hpp builds them; Schauffler, "Image-based object representation by
// layered impostors"). The quads go through the same scene program as the object's triangles,
// with the object's uniforms, and every scene program's fragment stage runs the impostor alpha
// test first (shaders/common/scene_main.glsl), so each technique sees a stand-in's fragments as
// it sees a mesh's. render/ knows only this description; lod/ decides what stands in for what.
#include "gl/objects.hpp"
#include "scene/scene.hpp"

#include <epoxy/gl.h>

#include <vector>

namespace strata {

struct StandInDraw {
    // Triangles: attribute 0 the position in the object's own space (drawn with its model
    // matrix), attribute 2 (u, v, atlas layer, slice).
    GLuint vertexArray = 0;
    // GL_TEXTURE_2D_ARRAY, RGBA8: rgb the object-space normal * 0.5 + 0.5, a the depth code
    // along the view's slice axis (0 empty; see shaders/common/scene_main.glsl).
    GLuint atlas = 0;
    // GL_TEXTURE_2D_ARRAY, SRGB8_ALPHA8, the atlas's texels: what the material's base colour
    // texture and COLOR_0 make of the surface there, colour and alpha; 0 where the material has
    // neither (its factors shade the stand-in alone).
    GLuint albedo = 0;
    int slices = 1;          // L: every stack's number of depth slices (1..256)
    float overlap = 0.0f;    // slice widths each slice's interval reaches past its own, each side
    // The vertex ranges (glMultiDrawArrays, GL_TRIANGLES) drawn this frame; none: the object
    // draws nothing (a part of a LOD unit whose representative draws the unit's stand-in).
    std::vector<GLint> first;
    std::vector<GLsizei> count;
    // World bounds of what the quads show (a LOD unit's parts): culling and back-to-front
    // sorting use them in the object's place. Empty: the object's own.
    Bounds worldBounds;
};

// Whether two stand-ins draw the same quads from the same atlas with the same slice settings and
// ranges: objects whose stand-ins are the same then differ only in their records, and one
// instanced draw takes them all (GpuScene::drawObjects). The world bounds do not matter.
bool sameStandInDraw(const StandInDraw& a, const StandInDraw& b);
// A strict weak order under which sameStandInDraw's stand-ins are equivalent: sorting by it puts
// the stand-ins one instanced draw can take next to each other.
bool standInDrawBefore(const StandInDraw& a, const StandInDraw& b);

// Per object (indexed like GpuScene::objects()): what draws in its place, or null for its own
// triangles. Held by the caller for the frame.
using StandIns = std::vector<const StandInDraw*>;

// A stand-in's vertex: position xyz (attribute 0), then u, v, atlas layer, slice (attribute 2),
// all floats, interleaved in one buffer.
inline constexpr int kStandInFloatsPerVertex = 7;

// The vertex array that reads `buffer` in that layout (attribute 1, the normal, stays off: the
// atlas has the normals).
gl::VertexArray makeStandInVertexArray(GLuint buffer);

}  // namespace strata
