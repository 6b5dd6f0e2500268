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
    : buffer_(std::move(other.buffer_)),
      mapped_(std::exchange(other.mapped_, nullptr)),
      fence_(std::exchange(other.fence_, nullptr)) {}

PassCounters& PassCounters::operator=(PassCounters&& other) noexcept {
    if (this != &other) {
        if (fence_) glDeleteSync(fence_);
        buffer_ = std::move(other.buffer_);
        mapped_ = std::exchange(other.mapped_, nullptr);
        fence_ = std::exchange(other.fence_, nullptr);
    }
    return *this;
}

void PassCounters::reset() {
    if (!buffer_) {
        buffer_ = Buffer::create();
        const GLbitfield flags = GL_MAP_READ_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
        glNamedBufferStorage(buffer_.id(), kBytes, nullptr, flags);
        mapped_ = static_cast<const volatile std::uint32_t*>(glMapNamedBufferRange(buffer_.id(), 0, kBytes, flags));
        if (!mapped_) throw std::runtime_error("could not map a pass's counter buffer");
    }
    if (fence_) {
        glDeleteSync(fence_);
        fence_ = nullptr;
    }
    glClearNamedBufferSubData(buffer_.id(), GL_R32UI, 0, kBytes, GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
}

void PassCounters::bind(GLuint binding) const { glBindBufferBase(GL_ATOMIC_COUNTER_BUFFER, binding, buffer_.id()); }

void PassCounters::fence() {
    // Shader atomics are incoherent writes: the barrier makes them visible through the mapping.
    glMemoryBarrier(GL_CLIENT_MAPPED_BUFFER_BARRIER_BIT);
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
