#include "gl/objects.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace strata::gl {

Texture createTexture2D(GLenum internalFormat, int width, int height) {
    Texture t = createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(t.id(), 1, internalFormat, width, height);
    glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return t;
}

Framebuffer createFramebuffer(const std::vector<GLuint>& colors) {
    Framebuffer fbo = Framebuffer::create();
    std::vector<GLenum> buffers;
    for (std::size_t i = 0; i < colors.size(); ++i) {
        glNamedFramebufferTexture(fbo.id(), GLenum(GL_COLOR_ATTACHMENT0 + i), colors[i], 0);
        buffers.push_back(GLenum(GL_COLOR_ATTACHMENT0 + i));
    }
    glNamedFramebufferDrawBuffers(fbo.id(), GLsizei(buffers.size()), buffers.data());
    return fbo;
}

std::uint64_t storageBlockElements(std::uint64_t elementBytes, double capMiB) {
    GLint64 limit = 0;
    glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &limit);
    std::uint64_t bytes = std::uint64_t(std::max<GLint64>(limit, 1 << 20));
    if (capMiB > 0) bytes = std::min<std::uint64_t>(bytes, std::uint64_t(capMiB * 1024 * 1024));
    return std::max<std::uint64_t>(bytes / elementBytes, 1);
}

void allocateBuffer(Buffer& buffer, std::size_t bytes, GLenum usage, const char* what) {
    if (!buffer) buffer = Buffer::create();
    while (glGetError() != GL_NO_ERROR) {}
    glNamedBufferData(buffer.id(), GLsizeiptr(bytes == 0 ? 4 : bytes), nullptr, usage);
    if (glGetError() == GL_OUT_OF_MEMORY)
        throw std::runtime_error(std::string("out of GPU memory allocating ") + what + " (" +
                                 std::to_string(bytes) + " bytes)");
}

GLuint readUint(const Buffer& buffer) {
    GLuint value = 0;
    glGetNamedBufferSubData(buffer.id(), 0, sizeof(GLuint), &value);
    return value;
}

}  // namespace strata::gl
