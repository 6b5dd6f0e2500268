#include "oit/peeling/peel_loop.hpp"

#include "oit/peeling/object_skipper.hpp"

#include <algorithm>

namespace strata::peeling {

PeelLoop::PeelLoop(const FrameContext& frame, TechniqueStats& stats, ObjectSkipper& skipper, bool skip)
    : stats_(stats), skipper_(skipper) {
    stats_ = {};
    skipper_.beginFrame(frame, skip);
}

void PeelLoop::setTotal(std::uint64_t total) { total_ = remaining_ = total; }

int PeelLoop::run(const PeelLoopOptions& options, const std::function<PeelStep(int)>& step) {
    // runAhead with nothing issued ahead: each iteration issued and collected in one go.
    PeelLoopOptions waiting = options;
    waiting.takenAtMost = 0;
    PeelStep last;
    return runAhead(waiting, [&](int iteration) { last = step(iteration); }, [&](int) { return last; });
}

int PeelLoop::runAhead(const PeelLoopOptions& options, const std::function<void(int)>& issue,
                       const std::function<PeelStep(int)>& collect) {
    // Iterations [collected, issued) are in flight; `certain` is what remains for certain once
    // they are done.
    int issued = 0, collected = 0;
    auto certainAfterInFlight = [&] {
        const std::uint64_t inFlight = options.takenAtMost * std::uint64_t(issued - collected);
        return remaining_ > inFlight ? remaining_ - inFlight : 0;
    };
    auto collectNext = [&] {
        const PeelStep s = collect(collected++);
        stats_.fragmentsCaptured += s.kept;
        overflow_ += s.overflow;
        return s;
    };
    for (;;) {
        if (collected == issued) {
            if (issued >= options.maxPasses) {
                stats_.overflowed = true;
                break;
            }
            if (issued > 0 && options.between) options.between(issued - 1);
            issue(issued++);
        }
        while (options.takenAtMost > 0 && issued - collected < kInFlightAtMost && issued < options.maxPasses &&
               certainAfterInFlight() > 0) {
            if (options.between) options.between(issued - 1);
            issue(issued++);
        }
        const PeelStep s = collectNext();
        if (s.layer == 0 || !s.more || s.layer >= remaining_) break;
        remaining_ -= s.layer;
    }
    // Issued behind the end (the one case above): collected, so that nothing is left in flight.
    while (collected < issued) collectNext();
    return issued;
}

void PeelLoop::finish() {
    skipper_.endFrame(stats_);
    // Dropped: coincident fragments a strict test never peels (not an overflow), what did not fit
    // (overflow), and what the pass bound left behind (an overflow).
    stats_.fragmentsDropped = total_ - std::min(total_, stats_.fragmentsCaptured);
    if (overflow_ > 0) stats_.overflowed = true;
}

void clearAccumulation(GLuint color, GLuint passes) {
    const float nothingComposited[4] = {0, 0, 0, 1};
    glClearTexImage(color, 0, GL_RGBA, GL_FLOAT, nothingComposited);
    if (passes) {
        const float nothingAbsorbed[4] = {1, 1, 1, 1};
        glClearTexImage(passes, 0, GL_RGBA, GL_FLOAT, nothingAbsorbed);
    }
}

}  // namespace strata::peeling
