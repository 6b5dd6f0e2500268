#pragma once
// Skipping of fully peeled objects (depth-fighting paper, section 3.3). After a peel pass the
// per-pixel bound of what is left to peel is known (f2b: the last peeled depth; dual: the next
// nearest and farthest depths). An object whose (slightly inflated) bounding box has no sample
// on the remaining side of that bound anywhere cannot contribute again. Each live object's box
// is drawn under an occlusion query; the next pass draws the object under conditional rendering
// on that query (GL_QUERY_WAIT: the GPU waits, the CPU does not), and once a result is known on
// the CPU to be zero the object stays culled for the rest of the frame (a box behind the bound
// stays behind it: the remaining range only shrinks) and gets no more queries.
//
// Counting is exact, not guessed: a draw skipped on the CPU is counted when skipped; a draw
// issued under conditional rendering is counted as skipped after the frame if and only if its
// query result was zero (with GL_QUERY_WAIT the GPU skips exactly those).
#include "oit/technique.hpp"
#include "render/scene_program.hpp"

#include <vector>

namespace strata::peeling {

// Which side of the bound in `remaining` still holds unpeeled fragments (reversed-Z).
enum class RemainingSide {
    NotNearerThanR,   // z <= texel.r, with texel.r > 0 (f2b last depth; dual next nearest)
    NotFartherThanG,  // z >= -texel.g (dual next farthest, stored negated)
};

class ObjectSkipper {
public:
    // Forgets last frame's culling. `enabled` false: every object is drawn in every pass.
    void beginFrame(const FrameContext& frame, bool enabled);

    // Draws the boxes of the live objects against `remaining`; one query per object and side.
    // Several sides: an object is live only while every side's query passes.
    void query(const FrameContext& frame, GLuint remaining, const std::vector<RemainingSide>& sides);

    // Binds `program` and draws the live objects in submission order; adds to objectDraws and
    // objectDrawsSkipped for the draws it decides on now.
    void draw(const FrameContext& frame, const SceneProgram& program, TechniqueStats& stats);

    // Reads the results of the conditional draws and moves the skipped ones from objectDraws to
    // objectDrawsSkipped. Call once the frame's passes are issued.
    void endFrame(TechniqueStats& stats);

    // Bounding-box draws issued for queries this frame (their cost is not an object draw).
    std::uint64_t boxDraws() const { return boxDraws_; }

private:
    struct Pending {
        std::vector<GLuint> queries;  // the latest query per side
    };
    struct Conditional {
        GLuint query;
    };

    GLuint nextQuery();
    void ensureBox();

    bool enabled_ = false;
    std::vector<bool> culled_;
    std::vector<Pending> pending_;
    std::vector<Conditional> conditional_;
    std::vector<gl::Query> pool_;
    std::size_t poolUsed_ = 0;
    std::uint64_t boxDraws_ = 0;
    gl::Program boxProgram_;
    GLint boxMin_ = -1, boxMax_ = -1, boxViewProj_ = -1, boxSide_ = -1;
    gl::VertexArray boxVao_;
    gl::Buffer boxVertices_, boxIndices_;
};

}  // namespace strata::peeling
