#pragma once
// The layer loop every depth peeling shares (f2b, f2b2, dual, the layer family f2b-ll/-fab/-kb
// and dual-ll/-fab, the coplanarity-aware f2b-2p, f2b-3p, dual-2p), written once: iterate until
// the layers are used up, stop on the pass bound (an overflow), keep the counts, and between
// iterations tell the object skipper (object_skipper.hpp) where what is left lies. Each technique
// supplies only its iteration (what it draws and what that found) and what it does between two.
//
// Stop rule. The loop knows how many transparent fragments there are (`total`, counted by the
// technique's first pass) and each iteration says how many it took out of the range still to
// peel (`layer`, kept or not). It ends when an iteration takes nothing (a guard: a range with
// fragments has a layer), when what was taken reaches what remained (nothing lies behind: D
// layers cost exactly D iterations, no empty pass to find out), or when the iteration itself
// knows nothing is left (`more`, e.g. dual's interior count). Coincident fragments a strict test
// never peels make `remaining` an overestimate; the loop then ends on the iteration that finds
// nothing, as an exact count would have.
#include "oit/technique.hpp"

#include <cstdint>
#include <functional>

namespace strata::peeling {

class ObjectSkipper;

// What one iteration found.
struct PeelStep {
    std::uint64_t layer = 0;     // fragments it took out of the range still to peel, kept or not
    std::uint64_t kept = 0;      // of them, composited (added to fragmentsCaptured)
    std::uint64_t overflow = 0;  // counted but not stored for lack of space (an overflow)
    bool more = true;            // false: the iteration knows nothing is left to peel
};

struct PeelLoopOptions {
    int maxPasses = 0;  // iterations at most; needing more is an overflow
    // runAhead: the most fragments one iteration can take (f2b: one a pixel; dual: two); 0 reads
    // every iteration's count before the next is issued.
    std::uint64_t takenAtMost = 0;
    // Called between two iterations (never after the last): where the skipper learns what is
    // left, and what must precede the next iteration (f2b-ll's next anchor pass).
    std::function<void(int iteration)> between;
};

class PeelLoop {
public:
    // Starts a frame: clears `stats` and begins the skipper's frame (`skip`: skip peeled objects).
    PeelLoop(const FrameContext& frame, TechniqueStats& stats, ObjectSkipper& skipper, bool skip);

    // The fragments to peel, when the technique counts them before the loop; f2b counts them in
    // its first iteration and sets them from there (before returning its step).
    void setTotal(std::uint64_t total);
    std::uint64_t total() const { return total_; }
    std::uint64_t remaining() const { return remaining_; }

    // Runs `step(iteration)` from iteration 0 under the stop rule above; returns the iterations run.
    int run(const PeelLoopOptions& options, const std::function<PeelStep(int iteration)>& step);

    // The same stop rule with each iteration split in two: `issue` queues its passes, `collect`
    // reads what it found. Reading a count waits for the GPU to finish the pass, and the GPU then
    // idles until the next pass arrives (a bubble per iteration on a real GPU, measured at 0.2 to
    // 0.3 ms on an H100; llvmpipe runs each pass as it is issued). So the next iterations are
    // issued before the counts are read, while the counts already read prove there is more to
    // take: what remained less `takenAtMost` for each iteration in flight is still above zero.
    // Two in flight are enough: the GPU works on the next iteration while the CPU waits for the
    // last one's count. The rule stops exactly where run() stops but for one case: an iteration
    // that takes nothing (only coincident leftovers a strict test never peels) ends the loop
    // after the next one was issued, which takes nothing too and is counted (passes, draws) as
    // what it cost.
    int runAhead(const PeelLoopOptions& options, const std::function<void(int iteration)>& issue,
                 const std::function<PeelStep(int iteration)>& collect);

    // Ends the frame: the skipper's counts into the stats, fragmentsDropped (what was counted and
    // not kept), and overflowed when an iteration overflowed or the pass bound was reached.
    void finish();

private:
    static constexpr int kInFlightAtMost = 2;
    TechniqueStats& stats_;
    ObjectSkipper& skipper_;
    std::uint64_t total_ = 0, remaining_ = 0, overflow_ = 0;
};

// Clears an accumulation target to "nothing composited" (colour 0, transmittance 1) and, when
// given (`passes` != 0; the RGB build's), its per-channel transmittance target to 1.
void clearAccumulation(GLuint color, GLuint passes = 0);

}  // namespace strata::peeling
