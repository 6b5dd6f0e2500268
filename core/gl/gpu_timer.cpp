#include "gl/gpu_timer.hpp"

#include <cassert>

namespace strata::gl {

void GpuTimer::begin(std::string pass) {
    assert(!open_ && "timer queries cannot nest");
    std::size_t index = pending_.size();
    if (index >= pool_.size()) pool_.push_back(createQuery(GL_TIME_ELAPSED));
    glBeginQuery(GL_TIME_ELAPSED, pool_[index].id());
    pending_.push_back({std::move(pass), index, std::chrono::steady_clock::now()});
    open_ = true;
}

void GpuTimer::end() {
    assert(open_);
    glEndQuery(GL_TIME_ELAPSED);
    auto& p = pending_.back();
    p.cpuMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - p.cpuStart).count();
    open_ = false;
}

std::vector<PassTime> GpuTimer::resolve() {
    std::vector<PassTime> out;
    out.reserve(pending_.size());
    for (const auto& p : pending_) {
        GLuint64 ns = 0;
        glGetQueryObjectui64v(pool_[p.query].id(), GL_QUERY_RESULT, &ns);
        out.push_back({p.name, double(ns) * 1e-6, p.cpuMs});
    }
    pending_.clear();
    return out;
}

}  // namespace strata::gl
