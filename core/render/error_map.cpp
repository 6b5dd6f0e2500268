#include "render/error_map.hpp"

#include "common/bindings.h"
#include "debug/error_map.h"
#include "gl/shader_program.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>
#include <stdexcept>
#include <vector>

namespace strata {

static_assert(sizeof(gpu::ErrorPartial) == 16, "ErrorPartial is four 32-bit scalars in std430");

namespace {
constexpr float kRampStops[] = {ERROR_RAMP_STOPS};
static_assert(std::size(kRampStops) == 18, "six RGB stops");
}  // namespace

glm::vec3 errorMapRamp(float t) {
    // As the compute pass's ramp(): five segments over [0, 1].
    const float x = std::clamp(t, 0.0f, 1.0f) * 5.0f;
    const int i = std::min(int(x), 4);
    const glm::vec3 a(kRampStops[3 * i], kRampStops[3 * i + 1], kRampStops[3 * i + 2]);
    const glm::vec3 b(kRampStops[3 * i + 3], kRampStops[3 * i + 4], kRampStops[3 * i + 5]);
    return glm::mix(a, b, x - float(i));
}

Image errorMapImage(const Image& image, const Image& reference, float scale) {
    if (image.width != reference.width || image.height != reference.height)
        throw std::invalid_argument("error map: the image is " + std::to_string(image.width) + "x" +
                                    std::to_string(image.height) + ", its reference " + std::to_string(reference.width) +
                                    "x" + std::to_string(reference.height));
    if (!(scale > 0.0f)) throw std::invalid_argument("error map: scale must be > 0");
    Image out(image.width, image.height);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const glm::vec3 r = glm::vec3(reference.at(x, y));
            const glm::vec3 d = glm::abs(glm::vec3(image.at(x, y)) - r);
            const float worst = std::max(d.r, std::max(d.g, d.b));
            const float luminance = std::clamp(glm::dot(r, glm::vec3(0.2126f, 0.7152f, 0.0722f)), 0.0f, 1.0f);
            const glm::vec3 shown = worst == 0.0f ? glm::vec3(float(ERROR_SAME_BASE) + float(ERROR_SAME_GAIN) * luminance)
                                                  : errorMapRamp(worst / scale);
            out.set(x, y, glm::vec4(shown, 1.0f));
        }
    return out;
}

ErrorMap::ErrorMap() : program_(gl::buildProgram({"debug/error_map.comp.glsl"})) {
    scaleLocation_ = glGetUniformLocation(program_.id(), "uScale");
}

ErrorMapStats ErrorMap::compare(GLuint image, GLuint reference, glm::ivec2 size, float scale, bool falseColour) {
    if (size.x <= 0 || size.y <= 0) return {};
    if (!(scale > 0.0f)) throw std::invalid_argument("error map: scale must be > 0");
    gl::Texture& target = falseColour ? falseColor_ : scratch_;
    glm::ivec2& targetSize = falseColour ? size_ : scratchSize_;
    if (!target.id() || targetSize != size) {
        target = gl::createTexture2D(GL_RGBA32F, size.x, size.y);
        targetSize = size;
    }
    const GLuint group = gpu::ERROR_GROUP_SIZE;
    const GLuint groupsX = (GLuint(size.x) + group - 1) / group, groupsY = (GLuint(size.y) + group - 1) / group;
    const std::size_t groups = std::size_t(groupsX) * groupsY;
    if (groups > partialCapacity_) {
        gl::allocateBuffer(partials_, groups * sizeof(gpu::ErrorPartial), GL_DYNAMIC_READ, "error map partials");
        partialCapacity_ = groups;
    }

    glUseProgram(program_.id());
    glProgramUniform1f(program_.id(), scaleLocation_, scale);
    glBindTextureUnit(gpu::BIND_ERROR_IMAGE, image);
    glBindTextureUnit(gpu::BIND_ERROR_REFERENCE, reference);
    glBindImageTexture(gpu::BIND_RESOLVE_OUTPUT, target.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BIND_ERROR_PARTIALS, partials_.id());
    glDispatchCompute(groupsX, groupsY, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    glUseProgram(0);

    std::vector<gpu::ErrorPartial> partials(groups);
    glGetNamedBufferSubData(partials_.id(), 0, GLsizeiptr(groups * sizeof(gpu::ErrorPartial)), partials.data());

    ErrorMapStats s;
    s.pixels = std::size_t(size.x) * std::size_t(size.y);
    double sum = 0.0;
    float worst = -1.0f;
    std::uint64_t worstPixel = ~std::uint64_t(0);
    for (const gpu::ErrorPartial& p : partials) {
        sum += double(p.sumSquares);
        if (p.maxError > worst || (p.maxError == worst && p.maxPixel < worstPixel)) {
            worst = p.maxError;
            worstPixel = p.maxPixel;
        }
    }
    s.rmse = std::sqrt(sum / double(3 * s.pixels));
    s.psnr = s.rmse > 0.0 ? std::min(100.0, 20.0 * std::log10(1.0 / s.rmse)) : 100.0;
    s.maxAbsError = std::max(0.0f, worst);
    s.worstPixel = {int(worstPixel % std::uint64_t(size.x)), int(worstPixel / std::uint64_t(size.x))};
    return s;
}

}  // namespace strata
