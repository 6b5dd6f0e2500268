#include "gl/pass_counters.hpp"

#include <stdexcept>
#include <utility>

namespace strata::gl {
namespace {

constexpr GLsizeiptr kBytes = PassCounters::kSlots * sizeof(std::uint32_t);
constexpr GLuint64 kWaitNs = 60'000'000'000ull;

}  // namespace

PassCounters::~PassCounters() {
    if (fence_) glDeleteSync(fence_);
}

PassCounters::PassCounters(PassCounters&& other) noexcept
    : counters_(std::move(other.counters_)),
      readback_(std::move(other.readback_)),
      mapped_(std::exchange(other.mapped_, nullptr)),
      fence_(std::exchange(other.fence_, nullptr)) {}

PassCounters& PassCounters::operator=(PassCounters&& other) noexcept {
    if (this != &other) {
        if (fence_) glDeleteSync(fence_);
        counters_ = std::move(other.counters_);
        readback_ = std::move(other.readback_);
        mapped_ = std::exchange(other.mapped_, nullptr);
        fence_ = std::exchange(other.fence_, nullptr);
    }
    return *this;
}

void PassCounters::reset() {
    if (!counters_) {
        // No mapping flags: the driver keeps it in GPU memory, where the atomics run.
        counters_ = Buffer::create();
        glNamedBufferStorage(counters_.id(), kBytes, nullptr, 0);
        readback_ = Buffer::create();
        const GLbitfield flags = GL_MAP_READ_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
        glNamedBufferStorage(readback_.id(), kBytes, nullptr, flags);
        mapped_ = static_cast<const volatile std::uint32_t*>(glMapNamedBufferRange(readback_.id(), 0, kBytes, flags));
        if (!mapped_) throw std::runtime_error("could not map a pass's counter buffer");
    }
    if (fence_) {
        glDeleteSync(fence_);
        fence_ = nullptr;
    }
    glClearNamedBufferSubData(counters_.id(), GL_R32UI, 0, kBytes, GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
}

void PassCounters::bind(GLuint binding) const { glBindBufferBase(GL_ATOMIC_COUNTER_BUFFER, binding, counters_.id()); }

void PassCounters::fence() {
    // Shader atomics are incoherent writes: the barrier makes them visible to the copy. The
    // copy's own writes reach the coherent mapping once the fence has signalled.
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glCopyNamedBufferSubData(counters_.id(), readback_.id(), 0, 0, kBytes);
    if (fence_) glDeleteSync(fence_);
    fence_ = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
}

std::array<std::uint32_t, PassCounters::kSlots> PassCounters::read() {
    if (!fence_ || !mapped_) throw std::logic_error("pass counters read before a pass fenced them");
    const GLenum status = glClientWaitSync(fence_, GL_SYNC_FLUSH_COMMANDS_BIT, kWaitNs);
    if (status != GL_ALREADY_SIGNALED && status != GL_CONDITION_SATISFIED)
        throw std::runtime_error(status == GL_TIMEOUT_EXPIRED ? "the GPU did not finish a pass within a minute"
                                                              : "waiting for a pass's counters failed");
    std::array<std::uint32_t, kSlots> values{};
    for (int i = 0; i < kSlots; ++i) values[std::size_t(i)] = mapped_[i];
    return values;
}

}  // namespace strata::gl
