#include "oit/screendoor/screendoor_pass.hpp"

#include "oit/draw_transparent.hpp"

#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <string>

namespace strata::screendoor {

void setSamplingUniforms(GLuint p, const FrameContext& frame, const PassParameters& parameters) {
    const double tanHalfFov = std::tan(glm::radians(double(frame.camera.fovYDegrees)) / 2.0);
    const double samplesPerUnit = frame.size.y * parameters.factor / (2.0 * tanHalfFov);
    const glm::vec3 axis = frame.camera.forward();
    glProgramUniform1ui(p, glGetUniformLocation(p, "uSeed"), parameters.seed);
    glProgramUniform1f(p, glGetUniformLocation(p, "uSamplesPerUnit"), float(samplesPerUnit));
    glProgramUniform3fv(p, glGetUniformLocation(p, "uEyePosition"), 1, glm::value_ptr(frame.camera.position));
    glProgramUniform3fv(p, glGetUniformLocation(p, "uViewAxis"), 1, glm::value_ptr(axis));
    const glm::vec3 right = frame.camera.right();
    glProgramUniform3fv(p, glGetUniformLocation(p, "uViewRight"), 1, glm::value_ptr(right));
    glProgramUniform1f(p, glGetUniformLocation(p, "uNearPlane"), frame.camera.nearPlane);
}

DrawTile drawMaskedObjects(const SceneProgram& program) {
    return [&program](const FrameContext& tileFrame, glm::ivec2 tileOriginSamples) {
        const GLuint p = program.id();
        glProgramUniform2i(p, glGetUniformLocation(p, "uTileOriginSamples"), tileOriginSamples.x, tileOriginSamples.y);
        return drawTransparent(tileFrame, program, tileFrame.transparentOrder);
    };
}

TechniqueStats ScreenDoorPass::render(const FrameContext& frame, const PassParameters& parameters, const DrawTile& draw) {
    if (!samples_) samples_ = gl::createQuery(GL_SAMPLES_PASSED);
    const int n = parameters.factor;
    TechniqueStats stats;
    GLuint64 kept = 0;
    int drawnTiles = 0;
    for (const Tile& tile : supersampleTiles(frame.size, n)) {
        // Where no transparent object reaches, the output holds the opaque colour already: the
        // fill, the draw and the averages run only inside the transparent area, and a tile
        // outside it not at all.
        std::optional<PixelRect> area;
        if (frame.transparentArea) {
            area = transparentAreaWithin(frame, PixelRect{tile.origin, tile.size});
            if (area->empty()) continue;
        }
        ++drawnTiles;
        {
            gl::ScopedPass pass(frame.timer, std::string(parameters.name) + " draw");
            target_.begin(frame, tile, n, area);
            if (parameters.maskSide > 0) masks_.bind(parameters.maskSide, parameters.seed);
            FrameContext tileFrame = frame;
            tileFrame.viewProjection = tileClipTransform(frame.size, tile) * frame.viewProjection;
            glBeginQuery(GL_SAMPLES_PASSED, samples_.id());
            stats.objectDraws += draw(tileFrame, tile.origin * n);
            glEndQuery(GL_SAMPLES_PASSED);
            const std::uint64_t tileKept = gl::queryResult(samples_);
            kept += tileKept;
        }
        gl::ScopedPass pass(frame.timer, std::string(parameters.name) + " box filter");
        target_.resolve(frame, tile, n, area);
    }
    glDepthMask(GL_FALSE);
    stats.tiles = drawnTiles;
    stats.passes = drawnTiles * (1 + SupersampledTarget::passesPerTile(n));
    stats.bytes = (parameters.maskSide > 0 ? masks_.bytes() : 0) + target_.bytes();
    // Samples that a mask kept and the z-buffer passed, in output pixels (n^2 samples each).
    stats.fragmentsCaptured = (kept + std::uint64_t(n) * n / 2) / (std::uint64_t(n) * n);
    return stats;
}

}  // namespace strata::screendoor
