#include "render/deflection_warp.hpp"

#include "render/texture_readback.hpp"
#include "render/zoom.hpp"

#include "common/bindings.h"
#include "gl/shader_program.hpp"

#include <stdexcept>
#include <string>

namespace strata {

std::string_view deflectFilterName(DeflectFilter f) {
    return f == DeflectFilter::Nearest ? "nearest" : "bilinear";
}

DeflectFilter parseDeflectFilter(std::string_view name) {
    if (name == "nearest") return DeflectFilter::Nearest;
    if (name == "bilinear") return DeflectFilter::Bilinear;
    throw std::invalid_argument("unknown deflection filter `" + std::string(name) + "` (known: nearest, bilinear)");
}

glm::mat3 deflectionInverseMap(const DeflectionParams& params) {
    if (params.mode == DeflectMode::Homography) return params.homography;
    glm::mat3 m(1.0f);  // glm is column-major: column 2 holds the translation
    m[2] = glm::vec3(-params.shift, 1.0f);
    return m;
}

glm::mat3 homographyFromYDownForward(const glm::dmat3& forwardYDown, int height) {
    glm::dmat3 flip(1.0);
    flip[1][1] = -1.0;
    flip[2][1] = double(height);  // column 2, row 1: y' = h - y
    return glm::mat3(flip * glm::inverse(forwardYDown) * flip);
}

void DeflectionWarp::resize(glm::ivec2 size) {
    if (size.x <= 0 || size.y <= 0) throw std::invalid_argument("deflection size must be positive");
    if (size == size_) return;
    size_ = size;
    color_ = gl::createTexture2D(GL_RGBA32F, size.x, size.y);
    fbo_ = gl::Framebuffer::create();
    glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, color_.id(), 0);
    if (glCheckNamedFramebufferStatus(fbo_.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("deflection framebuffer incomplete");
}

void DeflectionWarp::apply(GLuint sourceTexture, glm::ivec2 size, const DeflectionParams& params) {
    const glm::ivec2 expected = zoomRenderSize(size, params.zoom);
    glm::ivec2 source{0, 0};
    glGetTextureLevelParameteriv(sourceTexture, 0, GL_TEXTURE_WIDTH, &source.x);
    glGetTextureLevelParameteriv(sourceTexture, 0, GL_TEXTURE_HEIGHT, &source.y);
    if (source != expected)
        throw std::invalid_argument("deflection source is " + std::to_string(source.x) + "x" + std::to_string(source.y) +
                                    ", zoom " + std::to_string(params.zoom) + " of " + std::to_string(size.x) + "x" +
                                    std::to_string(size.y) + " needs " + std::to_string(expected.x) + "x" +
                                    std::to_string(expected.y));
    resize(size);
    // The identity map with nearest sampling is pure replication (or a copy at zoom 1): a program
    // of its own that skips the map, the bounds test and the filter branch.
    const bool replicate = params.mode == DeflectMode::Shift && params.shift == glm::vec2(0.0f) &&
                           params.filter == DeflectFilter::Nearest;
    if (replicate && !replicateProgram_)
        replicateProgram_ = gl::buildProgram({"common/fullscreen.vert.glsl", "frame/deflect.frag.glsl"}, {{"REPLICATE", ""}});
    if (!program_) {
        program_ = gl::buildProgram({"common/fullscreen.vert.glsl", "frame/deflect.frag.glsl"});
        emptyVertexArray_ = gl::VertexArray::create();
        counter_ = gl::Buffer::create();
        glNamedBufferStorage(counter_.id(), sizeof(GLuint), nullptr, GL_DYNAMIC_STORAGE_BIT);
    }
    const GLuint p = replicate ? replicateProgram_.id() : program_.id();
    const glm::mat3 map = deflectionInverseMap(params);
    glProgramUniformMatrix3fv(p, glGetUniformLocation(p, "uMap"), 1, GL_FALSE, &map[0][0]);
    glProgramUniform1i(p, glGetUniformLocation(p, "uBilinear"), params.filter == DeflectFilter::Bilinear ? 1 : 0);
    glProgramUniform1i(p, glGetUniformLocation(p, "uCount"), params.countOutside ? 1 : 0);
    glProgramUniform4fv(p, glGetUniformLocation(p, "uBorder"), 1, &params.border[0]);
    glProgramUniform1i(p, glGetUniformLocation(p, "uZoom"), params.zoom);
    glProgramUniform2i(p, glGetUniformLocation(p, "uDisplaySize"), size.x, size.y);
    counted_ = params.countOutside;
    if (counted_) {
        const GLuint zero = 0;
        glNamedBufferSubData(counter_.id(), 0, sizeof(GLuint), &zero);
    }
    // Bound even when not counting: the shader declares the counter, and a draw whose program
    // uses an atomic counter binding with no buffer behind it is undefined (Mesa ignores it,
    // other drivers need not), whether or not the increment runs.
    glBindBufferBase(GL_ATOMIC_COUNTER_BUFFER, gpu::BIND_COUNTERS, counter_.id());

    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glViewport(0, 0, size.x, size.y);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
    glDepthMask(GL_FALSE);
    glBindTextureUnit(gpu::BIND_SOURCE, sourceTexture);
    glUseProgram(p);
    glBindVertexArray(emptyVertexArray_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

std::uint64_t DeflectionWarp::outsidePixels() const {
    if (!counted_) return 0;
    glMemoryBarrier(GL_ATOMIC_COUNTER_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    return gl::readUint(counter_);
}

Image DeflectionWarp::readOutput() const { return readRgbaTexture(color_.id(), size_); }

}  // namespace strata
