#include "oit/buffers/bounded_buffer.hpp"

#include "common/bindings.h"

namespace strata::buffers {

void PixelImage::ensure(glm::ivec2 size) {
    if (size == size_) return;
    texture_ = gl::createTexture2D(GL_R32UI, size.x, size.y);
    size_ = size;
}

void PixelImage::clear() const {
    GLuint zero = 0;
    glClearTexImage(texture_.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
}

void PixelImage::bind(unsigned unit) const {
    glBindImageTexture(unit, texture_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
}

bool SizedBuffer::ensure(std::uint64_t count, std::uint64_t elementBytes, const char* label) {
    if (count == count_) return false;
    gl::allocateBuffer(buffer_, count * elementBytes, GL_DYNAMIC_COPY, label);
    count_ = count;
    return true;
}

std::string BoundedBufferFrame::storePassName(int /*pass*/) const { return id_ + " store"; }

void BoundedBufferFrame::renderFrame(const FrameContext& frame, const std::string& id, const Bounds& bounds,
                                     TechniqueStats& stats) {
    id_ = id;
    const std::optional<Shaders> lighter = lighterShaders(frame);
    const Shaders s = lighter ? *lighter : shaders();
    const ColorModel model = colorModelFor(frame.scene);
    current_ = &programs_[lighter ? 1 : 0][int(model)];
    SceneProgram& storeProgram = current_->store;
    gl::Program& resolveProgram = current_->resolve;
    if (!storeProgram.program) {
        storeProgram = buildSceneProgram(s.store, withColorModel(s.storeDefines, model));
        resolveProgram = gl::buildProgram(s.resolve, withColorModel(s.resolveDefines, model));
    }
    tailTargets_.setPrecision(bounds.tailPrecision);
    allocate(frame, bounds.capacity);
    stats = {};
    clear();
    counters_.reset();
    counters_.bind();
    bindStorage();
    setUniforms(storeProgram.id(), frame, bounds.capacity);
    for (int p = 0; p < storePasses(); ++p) {
        gl::ScopedPass pass(frame.timer, storePassName(p));
        tailTargets_.bindForStore(frame, bounds.tail && storePassWritesTail(p), true);
        setTransparentDepthState(frame);
        beginStorePass(p);
        stats.objectDraws += drawTransparent(frame, storeProgram, frame.transparentOrder);
        TailTargets::endStore();
        storeBarrier();
        ++stats.passes;
    }
    const bool texels = s.nodeTexels && nodeTexelsFit();
    if (texels && !current_->resolveTexels) {
        gl::Defines defines = withColorModel(s.resolveDefines, model);
        defines["NODE_TEXELS"] = "";
        current_->resolveTexels = gl::buildProgram(s.resolve, defines);
    }
    {
        gl::ScopedPass pass(frame.timer, id + " resolve");
        const GLuint program = texels ? current_->resolveTexels.id() : resolveProgram.id();
        bindStorage();
        glBindTextureUnit(gpu::BIND_OPAQUE_COLOR, frame.targets.opaqueColor());
        tailTargets_.bindForResolve(frame, bounds.tail);
        setUniforms(program, frame, bounds.capacity);
        glProgramUniform1i(program, glGetUniformLocation(program, "uTail"), bounds.tail);
        setDepthOrderUniforms(frame, program);
        const GLuint target = prepareResolve(frame, program);
        glBindFramebuffer(GL_FRAMEBUFFER, target);
        // Into the output, which holds the opaque colour where nothing transparent lies: only
        // where it can (a volume walk writes a target of its own, whole).
        std::optional<TransparentAreaScissor> scissor;
        if (target == frame.targets.outputFramebuffer()) scissor.emplace(frame);
        drawFullscreen(frame, program);
        ++stats.passes;
    }
    const StoreCounts c = counts(counters_.read(), frame, bounds.capacity);
    stats.fragmentsCaptured = c.captured;
    stats.overflowed = c.overflow > 0;
    (bounds.tail ? stats.fragmentsTail : stats.fragmentsDropped) = c.overflow;
    stats.bytes = storageBytes(frame, bounds.capacity) + tailTargets_.bytes(bounds.tail, frame.size);
    finishResolve(stats);
}

}  // namespace strata::buffers
