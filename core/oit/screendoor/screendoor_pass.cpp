#include "oit/screendoor/screendoor_pass.hpp"

#include "oit/draw_transparent.hpp"

#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <string>

namespace strata::screendoor {

TechniqueStats ScreenDoorPass::render(const FrameContext& frame, const SceneProgram& program,
                                      const PassParameters& parameters) {
    if (!samples_) samples_ = gl::createQuery(GL_SAMPLES_PASSED);
    const int n = parameters.factor;
    const GLuint p = program.id();
    const double tanHalfFov = std::tan(glm::radians(double(frame.camera.fovYDegrees)) / 2.0);
    glProgramUniform1ui(p, glGetUniformLocation(p, "uSeed"), parameters.seed);
    glProgramUniform1f(p, glGetUniformLocation(p, "uSamplesPerUnit"), float(frame.size.y * n / (2.0 * tanHalfFov)));
    glProgramUniform3fv(p, glGetUniformLocation(p, "uEyePosition"), 1, glm::value_ptr(frame.camera.position));
    const glm::vec3 axis = frame.camera.forward();
    glProgramUniform3fv(p, glGetUniformLocation(p, "uViewAxis"), 1, glm::value_ptr(axis));
    const GLint tileOrigin = glGetUniformLocation(p, "uTileOriginSamples");
    masks_.bind(parameters.maskSide, parameters.seed);

    TechniqueStats stats;
    GLuint64 kept = 0;
    const std::vector<Tile> tiles = supersampleTiles(frame.size, n);
    for (const Tile& tile : tiles) {
        {
            gl::ScopedPass pass(frame.timer, std::string(parameters.name) + " draw");
            target_.begin(frame, tile, n);
            glProgramUniform2i(p, tileOrigin, tile.origin.x * n, tile.origin.y * n);
            FrameContext tileFrame = frame;
            tileFrame.viewProjection = tileClipTransform(frame.size, tile) * frame.viewProjection;
            masks_.bind(parameters.maskSide, parameters.seed);
            glBeginQuery(GL_SAMPLES_PASSED, samples_.id());
            stats.objectDraws += drawTransparent(tileFrame, program, frame.transparentOrder);
            glEndQuery(GL_SAMPLES_PASSED);
            GLuint64 tileKept = 0;
            glGetQueryObjectui64v(samples_.id(), GL_QUERY_RESULT, &tileKept);
            kept += tileKept;
        }
        gl::ScopedPass pass(frame.timer, std::string(parameters.name) + " box filter");
        target_.resolve(frame, tile, n);
    }
    glDepthMask(GL_FALSE);
    stats.tiles = int(tiles.size());
    stats.passes = int(tiles.size()) * (1 + SupersampledTarget::passesPerTile(n));
    stats.bytes = masks_.bytes() + target_.bytes();
    // Samples that a mask kept and the z-buffer passed, in output pixels (n^2 samples each).
    stats.fragmentsCaptured = (kept + std::uint64_t(n) * n / 2) / (std::uint64_t(n) * n);
    return stats;
}

}  // namespace strata::screendoor
