#pragma once
// GPU time per pass from timer queries (a GL_TIMESTAMP pair per pass), with the CPU wall time
// beside it. Passes are sequential, not nested; results are read after the frame.
#include "gl/objects.hpp"

#include <chrono>
#include <string>
#include <vector>

namespace strata::gl {

struct PassTime {
    std::string name;
    double gpuMs = 0.0;
    double cpuMs = 0.0;
    // The GPU clock at the pass's two stamps (ns). Passes that overlap on the GPU (issued ahead
    // of a read, PeelLoop::runAhead) can add up to more than the span from first to last stamp.
    GLuint64 beginNs = 0, endNs = 0;
};

class GpuTimer {
public:
    void begin(std::string pass);
    void end();
    // Waits for the queries of this frame and returns their times; resets for the next frame.
    std::vector<PassTime> resolve();

private:
    struct Pending {
        std::string name;
        std::size_t query;
        std::chrono::steady_clock::time_point cpuStart;
        double cpuMs = 0.0;
    };
    std::vector<Query> pool_;
    std::vector<Pending> pending_;
    bool open_ = false;
};

// RAII scope: times a pass when a timer is given, does nothing otherwise.
class ScopedPass {
public:
    ScopedPass(GpuTimer* timer, std::string pass) : timer_(timer) { if (timer_) timer_->begin(std::move(pass)); }
    ~ScopedPass() { if (timer_) timer_->end(); }
    ScopedPass(const ScopedPass&) = delete;
    ScopedPass& operator=(const ScopedPass&) = delete;

private:
    GpuTimer* timer_;
};

}  // namespace strata::gl
