#include "oit/volume/volume_resolve.hpp"

#include "common/bindings.h"
#include "oit/volume/volume_bindings.h"
#include "render/shading.hpp"
#include "render/volume_composite.hpp"
#include "scene/mesh_volume.hpp"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <stdexcept>

namespace strata {

bool VolumeResolve::needed(const GpuScene& scene) {
    for (const ObjectVolume& v : scene.objectVolumes())
        if (v.volume) return true;
    return false;
}

static_assert(int(gpu::VOLUME_MAX_NESTED) == kMaxNestedVolumes, "CPU and GPU walks nest alike");
static_assert(sizeof(gpu::VolumeObject) == 24, "two RGB32F texels per VolumeObject");

void VolumeResolve::prepare(const FrameContext& frame) {
    const GpuScene& scene = frame.scene;
    const auto& objects = scene.objects();
    const auto& kinds = scene.objectVolumes();
    std::vector<gpu::VolumeObject> table(std::max<std::size_t>(objects.size(), 1));
    eyeInside_.clear();
    for (std::size_t i = 0; i < objects.size(); ++i) {
        if (!kinds[i].volume) continue;
        const VolumeMedium m = mediumOf(scene.scene().materials[std::size_t(objects[i].material)]);
        table[i] = {m.tau.r, m.tau.g, m.tau.b, m.scatter.r, m.scatter.g, m.scatter.b};
        const Bounds& b = objects[i].worldBounds;
        const glm::vec3 eye = frame.camera.position;
        const bool inBounds = glm::all(glm::greaterThanEqual(eye, b.min)) && glm::all(glm::lessThanEqual(eye, b.max));
        if (inBounds && containsPoint(scene.scene().meshes[std::size_t(objects[i].mesh)], objects[i].world, eye))
            eyeInside_.push_back(int(i));
    }
    if (table.size() != objectCapacity_) {
        gl::allocateBuffer(objects_, table.size() * sizeof(gpu::VolumeObject), GL_DYNAMIC_DRAW, "volume medium table");
        objectCapacity_ = table.size();
        media_ = gl::createTexture(GL_TEXTURE_BUFFER);
        glTextureBuffer(media_.id(), GL_RGB32F, objects_.id());
    }
    glNamedBufferSubData(objects_.id(), 0, GLsizeiptr(table.size() * sizeof(gpu::VolumeObject)), table.data());
    if (!stats_) {
        stats_ = gl::Buffer::create();
        glNamedBufferStorage(stats_.id(), gpu::VOLUME_STAT_COUNT * sizeof(GLuint), nullptr,
                             GL_DYNAMIC_STORAGE_BIT | GL_MAP_READ_BIT);
    }
    const GLuint zero[gpu::VOLUME_STAT_COUNT] = {};
    glNamedBufferSubData(stats_.id(), 0, sizeof(zero), zero);
}

void VolumeResolve::bind(const FrameContext& frame, GLuint program) const {
    glBindTextureUnit(gpu::BIND_VOLUME_MEDIA, media_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BIND_VOLUME_STATS, stats_.id());
    glBindTextureUnit(gpu::BIND_OPAQUE_DEPTH, frame.targets.depth());
    const double n = frame.camera.nearPlane, f = frame.camera.farPlane;
    auto at = [&](const char* name) { return glGetUniformLocation(program, name); };
    glProgramUniform1f(program, at("uDepthScale"), float(n * f / (f - n)));
    glProgramUniform2f(program, at("uInvFocal"), 1.0f / frame.projection[0][0], 1.0f / frame.projection[1][1]);
    glProgramUniform2f(program, at("uFrameSize"), float(frame.size.x), float(frame.size.y));
    const glm::mat3 eyeToWorld = glm::mat3_cast(glm::normalize(frame.camera.orientation));
    glProgramUniformMatrix3fv(program, at("uEyeToWorld"), 1, GL_FALSE, glm::value_ptr(eyeToWorld));
    const glm::vec3 light = glm::normalize(frame.scene.scene().lightDirection);
    glProgramUniform3fv(program, at("uLightDirection"), 1, glm::value_ptr(light));
    // L^a and L^r as render/volume_composite.hpp defines them.
    glProgramUniform1f(program, at("uAmbientRadiance"), kAmbient);
    glProgramUniform1f(program, at("uLightIrradiance"), glm::pi<float>() * (1.0f - kAmbient));
    const int inside = int(std::min<std::size_t>(eyeInside_.size(), gpu::VOLUME_MAX_NESTED));
    glProgramUniform1i(program, at("uEyeInsideCount"), inside);
    if (inside > 0) {
        std::vector<GLuint> ids(eyeInside_.begin(), eyeInside_.begin() + inside);
        glProgramUniform1uiv(program, at("uEyeInsideObject"), inside, ids.data());
    }
}

GLuint VolumeResolve::colorFramebuffer(const FrameContext& frame) {
    // Attached every frame: a new target may have the name of a deleted one, so comparing
    // names cannot tell whether the attachment is still the frame's.
    const bool created = !colorFramebuffer_;
    if (created) colorFramebuffer_ = gl::Framebuffer::create();
    glNamedFramebufferTexture(colorFramebuffer_.id(), GL_COLOR_ATTACHMENT0, frame.targets.outputColor(), 0);
    // The output is always RGBA32F: completeness checked once, not every frame.
    if (created) {
        const GLenum status = glCheckNamedFramebufferStatus(colorFramebuffer_.id(), GL_FRAMEBUFFER);
        if (status != GL_FRAMEBUFFER_COMPLETE)
            throw std::runtime_error("volume resolve framebuffer incomplete (status " + std::to_string(status) + ")");
    }
    return colorFramebuffer_.id();
}

std::uint64_t VolumeResolve::nestingOverflow() const {
    static_assert(gpu::VOLUME_STAT_NESTING_OVERFLOW == 0u, "the overflow count is the buffer's first uint");
    // The resolve wrote the counter through an SSBO atomic: reading it back needs the barrier.
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    return gl::readUint(stats_);
}

void VolumeResolve::addStats(TechniqueStats& stats) const {
    stats.bytes += bytes();
    const std::uint64_t ignored = nestingOverflow();
    stats.fragmentsDropped += ignored;
    stats.overflowed = stats.overflowed || ignored > 0;
}

std::uint64_t VolumeResolve::bytes() const {
    return objectCapacity_ * sizeof(gpu::VolumeObject) + gpu::VOLUME_STAT_COUNT * sizeof(GLuint);
}

}  // namespace strata
