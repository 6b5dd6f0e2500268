#pragma once
// Skipping of fully peeled objects (depth-fighting paper, section 3.3). After a peel pass the
// per-pixel bound of what is left to peel is known (f2b: the last peeled depth; dual: the next
// nearest and farthest depths). An object whose (slightly inflated) bounding box lies wholly on
// the peeled side of that bound over its screen rectangle cannot contribute again.
//
// The test runs at reduced resolution: one pass reduces the bound to its maxima over
// kBlock x kBlock pixel blocks (the conservative side), then each live object's screen rectangle
// (in those blocks) is drawn with the box's depth range under an occlusion query. That costs
// 1 / kBlock^2 of drawing each box at full resolution, which for large flat objects (a stack of
// layers) cost as much as a peel pass. The next pass draws the object under conditional
// rendering on that query (GL_QUERY_WAIT: the GPU waits, the CPU does not), and once a result
// is known on the CPU to be zero the object stays culled for the rest of the frame (the
// remaining range only shrinks) and gets no more queries.
//
// Counting is exact, not guessed: a draw skipped on the CPU is counted when skipped; a draw
// issued under conditional rendering is counted as skipped after the frame if and only if its
// query result was zero (with GL_QUERY_WAIT the GPU skips exactly those).
#include "oit/technique.hpp"
#include "render/scene_program.hpp"
#include "render/screen_rect.hpp"

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

    // Reduces `remaining` to block maxima and tests each live object's screen rectangle and
    // depth range against them; one query per object. Several sides: an object is live only
    // where, in one block, the box meets every side's bound (one query, so that a conditional
    // draw on it skips exactly: on a GPU whose results come late, a query per side left the
    // draw conditional on the first side alone, and dual drew objects the second side culled).
    void query(const FrameContext& frame, GLuint remaining, const std::vector<RemainingSide>& sides);

    // Binds `program` and draws the live objects in submission order; adds to objectDraws and
    // objectDrawsSkipped for the draws it decides on now.
    void draw(const FrameContext& frame, const SceneProgram& program, TechniqueStats& stats);

    // Reads the results of the conditional draws and moves the skipped ones from objectDraws to
    // objectDrawsSkipped. Call once the frame's passes are issued.
    void endFrame(TechniqueStats& stats);

    // Query rectangles issued this frame, one per live object and query() (not object draws).
    std::uint64_t queryDraws() const { return queryDraws_; }

private:
    struct Pending {
        GLuint query = 0;  // the latest query, 0 while none is waiting
    };
    struct Conditional {
        GLuint query;
    };

    // An object's inflated bounding box on screen (render/screen_rect.hpp): its rectangle in NDC,
    // snapped outwards to whole reduced pixels, and its window depth range (reversed-Z).
    struct ScreenBox {
        glm::vec4 rect{-1.0f, -1.0f, 1.0f, 1.0f};
        PixelRect blocks;  // the same rectangle in reduced pixels: the blocks its query reads
        float farDepth = 0.0f, nearDepth = 1.0f;
        bool empty = false;
    };
    static constexpr int kBlock = 8;

    GLuint nextQuery();
    void ensurePrograms();
    void ensureReducedTarget(glm::ivec2 size);
    ScreenBox screenBox(const FrameContext& frame, const Bounds& b) const;

    bool enabled_ = false;
    std::vector<bool> culled_;
    std::vector<ScreenBox> boxes_;  // per object id, this frame
    PixelRect queriedBlocks_;       // the union of boxes_' blocks: all the reduction must write
    std::vector<Pending> pending_;
    std::vector<Conditional> conditional_;
    std::vector<int> unconditional_;  // draw()'s scratch: the objects it draws without a condition
    std::vector<gl::Query> pool_;
    std::size_t poolUsed_ = 0;
    std::uint64_t queryDraws_ = 0;
    gl::Program reduceProgram_, reduceNearProgram_, rectProgram_;  // reduceNear: r alone
    GLint rectLocation_ = -1, sidesLocation_ = -1, boxFarLocation_ = -1, boxNearLocation_ = -1;
    gl::VertexArray emptyVao_;
    glm::ivec2 reducedSize_{0, 0};
    gl::Texture reduced_;
    gl::Framebuffer reduceFbo_, queryFbo_;
};

}  // namespace strata::peeling
