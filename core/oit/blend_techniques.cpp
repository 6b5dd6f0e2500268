// The blending baselines: one geometry pass with fixed-function "over" blending, in submission
// order (blend-unsorted) or with objects sorted back to front (blend-sorted). Both are exact only
// when no two objects overlap out of order; neither resolves intersecting or coplanar surfaces.
#include "oit/draw_transparent.hpp"
#include "oit/technique_families.hpp"

namespace strata {
namespace {

class BlendTechnique final : public Technique {
public:
    BlendTechnique(TechniqueInfo info, bool sorted) : info_(std::move(info)), sorted_(sorted) {}
    const TechniqueInfo& info() const override { return info_; }

    void render(const FrameContext& frame) override {
        if (!program_.program) program_ = buildSceneProgram("oit/blend.frag.glsl");
        std::vector<int> order = sorted_ ? sortedBackToFront(frame) : frame.transparentOrder;
        gl::ScopedPass pass(frame.timer, "blend");
        glBindFramebuffer(GL_FRAMEBUFFER, frame.targets.outputFramebuffer());
        setTransparentDepthState(frame);
        glEnable(GL_BLEND);
        glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
        stats_ = {};
        stats_.passes = 1;
        // Every fragment that passes the depth test is blended: an occlusion query counts them.
        if (!samples_) samples_ = gl::createQuery(GL_SAMPLES_PASSED);
        glBeginQuery(GL_SAMPLES_PASSED, samples_.id());
        stats_.objectDraws = drawTransparent(frame, program_, order);
        glEndQuery(GL_SAMPLES_PASSED);
        glDisable(GL_BLEND);
        GLuint64 blended = 0;
        glGetQueryObjectui64v(samples_.id(), GL_QUERY_RESULT, &blended);
        stats_.fragmentsCaptured = blended;
    }

private:
    TechniqueInfo info_;
    bool sorted_;
    SceneProgram program_;
    gl::Query samples_;
};

TechniqueEntry blendUnsortedEntry() {
    TechniqueInfo info{"blend-unsorted", "baseline", false, false, "1", "none",
                       "alpha blending in submission order (wrong wherever objects arrive front to back)"};
    return {info, [info] { return std::make_unique<BlendTechnique>(info, false); }};
}

TechniqueEntry blendSortedEntry() {
    TechniqueInfo info{"blend-sorted", "baseline", false, false, "1", "none",
                       "alpha blending with objects sorted back to front by bounds centre"};
    return {info, [info] { return std::make_unique<BlendTechnique>(info, true); }};
}

}  // namespace

std::vector<TechniqueEntry> baselineEntries() { return {blendUnsortedEntry(), blendSortedEntry()}; }

}  // namespace strata
