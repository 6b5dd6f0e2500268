#pragma once
// Move-only RAII owners for OpenGL objects, created with direct state access (GL 4.5).
// A default-constructed owner holds nothing (name 0); `release()` hands the name over.
#include <epoxy/gl.h>

#include <cstdint>
#include <utility>
#include <vector>

namespace strata::gl {

template <typename Traits>
class Handle {
public:
    Handle() = default;
    explicit Handle(GLuint adopted) : name_(adopted) {}
    static Handle create() { return Handle(Traits::create()); }
    ~Handle() { reset(); }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    Handle(Handle&& other) noexcept : name_(std::exchange(other.name_, 0)) {}
    Handle& operator=(Handle&& other) noexcept {
        if (this != &other) { reset(); name_ = std::exchange(other.name_, 0); }
        return *this;
    }
    GLuint id() const { return name_; }
    explicit operator bool() const { return name_ != 0; }
    GLuint release() { return std::exchange(name_, 0); }
    void reset() { if (name_) Traits::destroy(name_); name_ = 0; }

private:
    GLuint name_ = 0;
};

struct BufferTraits {
    static GLuint create() { GLuint n = 0; glCreateBuffers(1, &n); return n; }
    static void destroy(GLuint n) { glDeleteBuffers(1, &n); }
};
struct VertexArrayTraits {
    static GLuint create() { GLuint n = 0; glCreateVertexArrays(1, &n); return n; }
    static void destroy(GLuint n) { glDeleteVertexArrays(1, &n); }
};
struct FramebufferTraits {
    static GLuint create() { GLuint n = 0; glCreateFramebuffers(1, &n); return n; }
    static void destroy(GLuint n) { glDeleteFramebuffers(1, &n); }
};
// Lets go of a program: one gl::buildProgram built is kept for the next build of the same text
// (gl/program_pool.hpp: why no program name is reused), any other is deleted; STRATA_PROGRAM_POOL=0
// deletes every one (gl/shader_program.cpp).
void deleteProgram(GLuint name);
struct ProgramTraits {
    static GLuint create() { return glCreateProgram(); }
    static void destroy(GLuint n) { deleteProgram(n); }
};
struct ShaderTraits {
    static void destroy(GLuint n) { glDeleteShader(n); }
};
struct TextureTraits {
    static void destroy(GLuint n) { glDeleteTextures(1, &n); }
};
struct QueryTraits {
    static void destroy(GLuint n) { glDeleteQueries(1, &n); }
};
struct SamplerTraits {
    static GLuint create() { GLuint n = 0; glCreateSamplers(1, &n); return n; }
    static void destroy(GLuint n) { glDeleteSamplers(1, &n); }
};

using Buffer = Handle<BufferTraits>;
using VertexArray = Handle<VertexArrayTraits>;
using Framebuffer = Handle<FramebufferTraits>;
using Program = Handle<ProgramTraits>;
using Shader = Handle<ShaderTraits>;
using Texture = Handle<TextureTraits>;
using Query = Handle<QueryTraits>;
using Sampler = Handle<SamplerTraits>;

inline Texture createTexture(GLenum target) { GLuint n = 0; glCreateTextures(target, 1, &n); return Texture(n); }
inline Query createQuery(GLenum target) { GLuint n = 0; glCreateQueries(target, 1, &n); return Query(n); }
// The query's result, waiting for it (a sample count, a primitive count, a timestamp).
inline std::uint64_t queryResult(const Query& query) {
    GLuint64 n = 0;
    glGetQueryObjectui64v(query.id(), GL_QUERY_RESULT, &n);
    return n;
}

// A 2D texture with immutable storage, nearest filtering, clamped.
Texture createTexture2D(GLenum internalFormat, int width, int height);

// A framebuffer drawing into `colors` (textures, level 0) as colour attachments 0, 1, ... in
// order, each its draw buffer: a multi-target pass's output locations in the same order.
Framebuffer createFramebuffer(const std::vector<GLuint>& colors);

// How many elements of `elementBytes` the largest shader storage block holds: the device's
// GL_MAX_SHADER_STORAGE_BLOCK_SIZE, or less when `capMiB` > 0 (a setting, used by tests to
// force tiling on small frames). At least 1.
std::uint64_t storageBlockElements(std::uint64_t elementBytes, double capMiB);

// The first uint of `buffer`: a counter the GPU wrote (the caller issues the barrier first).
GLuint readUint(const Buffer& buffer);

// A buffer with mutable-size semantics (glNamedBufferData) so it can be grown.
// Throws std::runtime_error naming `what` when the driver reports GL_OUT_OF_MEMORY.
void allocateBuffer(Buffer& buffer, std::size_t bytes, GLenum usage, const char* what);

}  // namespace strata::gl
