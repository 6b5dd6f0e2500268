#include "gl/gpu_timer.hpp"

#include "gl/context.hpp"

#include <cassert>
#include <string>

namespace strata::gl {
namespace {

// On a software rasterizer the "GPU" is the CPU and timestamps are taken when a command is
// queued, not when its rasterization finishes, so a pass's work spills into the next pass. There
// we drain the pipeline at each pass boundary; on a real GPU the timestamps are pipelined
// correctly and draining would only add stalls.
//
// Draining before the stamp is not enough on llvmpipe: a timestamp is binned into every screen
// tile of the current scene (all commands until the framebuffer changes or a flush) and reads
// as the latest time any thread processed it. Tiles run one after another, each with all of its
// commands, so a stamp that shares its scene with draws reads late by nearly all of their work:
// a pass's begin stamp swallowed the pass, and its end stamp whatever came next on the same
// framebuffer (the bench's fragment count, ~8 ms at 256x256 with 16 layers). So the stamp is
// also flushed right away, alone in its scene.
bool softwareRenderer() {
    static const bool software = currentDeviceInfo().software();
    return software;
}

}  // namespace

void GpuTimer::begin(std::string pass) {
    assert(!open_ && "timer queries cannot nest");
    // A pair of GL_TIMESTAMP queries per pass rather than GL_TIME_ELAPSED: llvmpipe reports the
    // first TIME_ELAPSED query on a new framebuffer as seconds of uptime; timestamps are exact
    // on every driver and give the same difference.
    if (softwareRenderer()) glFinish();
    std::size_t index = pending_.size() * 2;
    while (pool_.size() < index + 2) pool_.push_back(createQuery(GL_TIMESTAMP));
    glQueryCounter(pool_[index].id(), GL_TIMESTAMP);
    if (softwareRenderer()) glFlush();
    pending_.push_back({std::move(pass), index, std::chrono::steady_clock::now()});
    open_ = true;
}

void GpuTimer::end() {
    assert(open_);
    auto& p = pending_.back();
    if (softwareRenderer()) glFinish();
    glQueryCounter(pool_[p.query + 1].id(), GL_TIMESTAMP);
    if (softwareRenderer()) glFlush();
    p.cpuMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - p.cpuStart).count();
    open_ = false;
}

std::vector<PassTime> GpuTimer::resolve() {
    std::vector<PassTime> out;
    out.reserve(pending_.size());
    for (const auto& p : pending_) {
        GLuint64 start = 0, end = 0;
        glGetQueryObjectui64v(pool_[p.query].id(), GL_QUERY_RESULT, &start);
        glGetQueryObjectui64v(pool_[p.query + 1].id(), GL_QUERY_RESULT, &end);
        out.push_back({p.name, end > start ? double(end - start) * 1e-6 : 0.0, p.cpuMs, start, end});
    }
    pending_.clear();
    return out;
}

}  // namespace strata::gl
