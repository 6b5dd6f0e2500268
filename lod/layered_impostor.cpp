#include "lod/layered_impostor.hpp"

#include "gl/saved_state.hpp"
#include "gl/shader_program.hpp"
#include "lod/view_directions.hpp"

#include "lod/lod_bindings.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <set>

namespace strata::lod {

namespace {

constexpr int kFloatsPerVertex = kStandInFloatsPerVertex;
constexpr int kVerticesPerQuad = 6;  // two triangles, glMultiDrawArrays(GL_TRIANGLES)
// Slice acceptance is decided in float on the GPU; the CPU's rectangles count a texel for every
// slice within this much (in slice units) of the rule's boundary, so they never miss one.
constexpr double kAcceptMargin = 1e-4;

gl::Texture depthTexture(int resolution, GLenum format) {
    gl::Texture t = gl::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(t.id(), 1, format, resolution, resolution);
    glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    return t;
}

// The inclusive slice range [lo, hi] that accepts depth code `code` (lod-contract.md), widened by
// kAcceptMargin at the boundaries.
std::pair<int, int> acceptedSlices(int code, int slices, float overlap) {
    const double tL = (double(code) - 0.5) / 255.0 * double(slices);
    double lo, hi;
    if (overlap == 0.0f) {  // min(int(t * L), L - 1) == slice
        lo = std::floor(tL - kAcceptMargin);
        hi = std::floor(tL + kAcceptMargin);
    } else {  // |t - (s + 0.5) / L| <= (0.5 + overlap) / L  <=>  tL - 1 - overlap <= s <= tL + overlap
        lo = std::ceil(tL - 1.0 - double(overlap) - kAcceptMargin);
        hi = std::floor(tL + double(overlap) + kAcceptMargin);
    }
    return {std::clamp(int(lo), 0, slices - 1), std::clamp(int(hi), 0, slices - 1)};
}

// Places `part` for `program`'s next draw (shaders/lod/bake.vert.glsl's uModel, uNormalMatrix).
void setPartTransform(GLuint program, const BakePart& part) {
    const glm::mat3 normal = glm::transpose(glm::inverse(glm::mat3(part.transform)));
    glProgramUniformMatrix4fv(program, glGetUniformLocation(program, "uModel"), 1, GL_FALSE, glm::value_ptr(part.transform));
    glProgramUniformMatrix3fv(program, glGetUniformLocation(program, "uNormalMatrix"), 1, GL_FALSE, glm::value_ptr(normal));
}

// What a part's material makes of its base colour (the bake's albedo target), for `program`.
void setPartAlbedo(GLuint program, const GpuScene& scene, int objectIndex) {
    const BaseColorDetail d = scene.baseColorDetail(objectIndex);
    glProgramUniform1i(program, glGetUniformLocation(program, "uTextured"), d.textured);
    glProgramUniformMatrix3fv(program, glGetUniformLocation(program, "uBaseColorTransform"), 1, GL_FALSE,
                              glm::value_ptr(d.transform));
    glProgramUniform1i(program, glGetUniformLocation(program, "uBaseColorTexCoord"), d.texCoord);
    glProgramUniform1i(program, glGetUniformLocation(program, "uVertexColor"), d.vertexColor);
    glProgramUniform1f(program, glGetUniformLocation(program, "uFactorAlpha"), d.factorAlpha);
    glProgramUniform1f(program, glGetUniformLocation(program, "uAlphaCutoff"), d.alphaCutoff);
    if (d.textured) scene.bindMaterialTextures(objectIndex);
}

}  // namespace

std::string ImpostorSettings::validate() const {
    if (!isValidViewCount(views)) return "impostor views must be 12, 20 or 32, not " + std::to_string(views);
    if (resolution < 1 || resolution > 256)
        return "impostor resolution must be 1..256 texels, not " + std::to_string(resolution);
    if (slices < 1 || slices > 256) return "impostor slices must be 1..256, not " + std::to_string(slices);
    if (peels < 1 || peels > 4) return "impostor peels must be 1..4, not " + std::to_string(peels);
    if (!(overlap >= 0.0f) || !std::isfinite(overlap)) return "impostor overlap must be finite and >= 0";
    if (!(apexFactor > 1.0f) || !std::isfinite(apexFactor)) return "impostor apex factor must be finite and > 1";
    return {};
}

LayeredImpostor::LayeredImpostor(const GpuMesh& mesh, const Bounds& bounds, const ImpostorSettings& settings,
                                 BakeMaterial material)
    : LayeredImpostor(mesh.vertexArray.id(), mesh.indexCount, bounds, settings, material) {}

LayeredImpostor::LayeredImpostor(GLuint vertexArray, GLsizei indexCount, const Bounds& bounds,
                                 const ImpostorSettings& settings, BakeMaterial material)
    : LayeredImpostor(std::vector<BakePart>{{vertexArray, indexCount, glm::mat4(1.0f), material.objectIndex}}, bounds,
                      settings, material.scene) {}

LayeredImpostor::LayeredImpostor(const std::vector<BakePart>& parts, const Bounds& bounds,
                                 const ImpostorSettings& settings, const GpuScene* albedoScene)
    : settings_(settings) {
    if (settings_.peels > 1) settings_.overlap = 0.0f;
    reason_ = settings_.validate();
    if (!valid()) return;
    GLsizei indices = 0;
    for (const BakePart& part : parts) indices += part.indexCount;
    if (indices < 3) { reason_ = "the mesh has no triangles"; return; }
    if (bounds.empty()) { reason_ = "the mesh has no vertices"; return; }
    centre_ = bounds.center();
    radius_ = bounds.radius();
    if (!std::isfinite(radius_) || !(std::isfinite(centre_.x) && std::isfinite(centre_.y) && std::isfinite(centre_.z))) { reason_ = "the mesh's bounds are not finite"; return; }
    if (!(radius_ > 0.0f)) { reason_ = "the mesh's bounding sphere has zero radius"; return; }

    const auto start = std::chrono::steady_clock::now();
    directions_ = viewDirections(settings_.views);
    for (const auto& d : directions_) frames_.push_back(makeImpostorFrame(centre_, radius_, d, settings_.apexFactor));
    gl::SavedDrawState saved;
    bakeImages(parts, albedoScene);
    // One read-back: the rectangles need every texel's depth code.
    buildRectangles(readLayers(atlas_.id()));
    buildQuads();
    if (settings_.holeFilling) findHoleSlices(parts);
    mergeHoleSlices();
    glFinish();
    bakeMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

gl::Texture LayeredImpostor::layerTexture(GLenum format, int resolution, int layers) {
    gl::Texture t = gl::createTexture(GL_TEXTURE_2D_ARRAY);
    glTextureStorage3D(t.id(), 1, format, resolution, resolution, layers);
    glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return t;
}

std::vector<std::uint8_t> LayeredImpostor::readLayers(GLuint texture) const {
    std::vector<std::uint8_t> texels(std::size_t(settings_.resolution) * std::size_t(settings_.resolution) * 4u *
                                     std::size_t(settings_.views * settings_.peels));
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(texture, 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(texels.size()), texels.data());
    return texels;
}

void LayeredImpostor::bakeImages(const std::vector<BakePart>& parts, const GpuScene* albedoScene) {
    const int res = settings_.resolution, peels = settings_.peels;
    auto arrayTexture = [&](GLenum format) { return layerTexture(format, res, settings_.views * peels); };
    atlas_ = arrayTexture(GL_RGBA8);
    const bool withAlbedo = albedoScene != nullptr;
    // sRGB-encoded: 8 bits where the eye sees steps, as the textures it comes from.
    if (withAlbedo) albedo_ = arrayTexture(GL_SRGB8_ALPHA8);
    // Two depth targets: the peel being drawn and the previous one it peels beneath.
    gl::Texture depth[2] = {depthTexture(res, GL_DEPTH_COMPONENT32F), depthTexture(res, GL_DEPTH_COMPONENT32F)};
    gl::Framebuffer fbo = gl::Framebuffer::create();
    gl::Defines defines;
    if (withAlbedo) defines["BAKE_ALBEDO"] = "";
    gl::Program first = gl::buildProgram({"lod/bake.vert.glsl", "lod/bake.frag.glsl"}, defines);
    gl::Defines peelDefines = defines;
    peelDefines["PEEL"] = "";
    gl::Program peel = peels > 1 ? gl::buildProgram({"lod/bake.vert.glsl", "lod/bake.frag.glsl"}, peelDefines)
                                 : gl::Program();
    if (withAlbedo) {
        const GLenum both[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
        glNamedFramebufferDrawBuffers(fbo.id(), 2, both);
        glEnable(GL_FRAMEBUFFER_SRGB);  // linear out, sRGB stored (the normal atlas is not sRGB)
    }

    glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
    glViewport(0, 0, res, res);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glDisable(GL_STENCIL_TEST);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);  // depth 0 at the apex side: keep the surface farthest from the apex
    glDepthMask(GL_TRUE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    const float empty[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    const float clearDepth = 0.0f;
    for (int view = 0; view < settings_.views; ++view) {
        const ImpostorFrame& f = frames_[std::size_t(view)];
        const glm::mat4 viewProj = f.projection() * f.view();
        for (int p = 0; p < peels; ++p) {
            GLuint program = p == 0 ? first.id() : peel.id();
            glUseProgram(program);
            glProgramUniformMatrix4fv(program, glGetUniformLocation(program, "uViewProj"), 1, GL_FALSE,
                                      glm::value_ptr(viewProj));
            glProgramUniform3fv(program, glGetUniformLocation(program, "uApex"), 1, glm::value_ptr(f.apex));
            glProgramUniform3fv(program, glGetUniformLocation(program, "uAxis"), 1, glm::value_ptr(f.axis));
            glProgramUniform1f(program, glGetUniformLocation(program, "uSlabNear"), f.slabNear());
            glProgramUniform1f(program, glGetUniformLocation(program, "uSlabDepth"), 2.0f * f.radius);
            glNamedFramebufferTextureLayer(fbo.id(), GL_COLOR_ATTACHMENT0, atlas_.id(), 0, view * peels + p);
            if (withAlbedo) {
                glNamedFramebufferTextureLayer(fbo.id(), GL_COLOR_ATTACHMENT1, albedo_.id(), 0, view * peels + p);
                glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 1, empty);
            }
            glNamedFramebufferTexture(fbo.id(), GL_DEPTH_ATTACHMENT, depth[p % 2].id(), 0);
            if (p > 0) glBindTextureUnit(gpu::BIND_BAKE_PREVIOUS_DEPTH, depth[(p + 1) % 2].id());
            glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, empty);
            glClearNamedFramebufferfv(fbo.id(), GL_DEPTH, 0, &clearDepth);
            for (const BakePart& part : parts) {
                if (part.indexCount <= 0) continue;
                setPartTransform(program, part);
                if (withAlbedo) setPartAlbedo(program, *albedoScene, part.objectIndex);
                glBindVertexArray(part.vertexArray);
                glDrawElements(GL_TRIANGLES, part.indexCount, GL_UNSIGNED_INT, nullptr);
            }
        }
    }
    glBindTextureUnit(gpu::BIND_BAKE_PREVIOUS_DEPTH, 0);
    glDisable(GL_FRAMEBUFFER_SRGB);
}

void LayeredImpostor::buildRectangles(std::span<const std::uint8_t> texels, std::vector<SliceRect> baked) {
    levels_.clear();
    for (int slices = settings_.slices;; slices /= 2) {
        Level level;
        level.slices = slices;
        level.rects = levels_.empty() && !baked.empty() ? std::move(baked) : rectanglesFor(texels, slices);
        levels_.push_back(std::move(level));
        if (!settings_.mergedLevels || slices % 2 != 0 || slices / 2 < kLeastLevelSlices) break;
    }
}

std::vector<SliceRect> LayeredImpostor::rectanglesFor(std::span<const std::uint8_t> texels, int L) const {
    const int res = settings_.resolution, layers = settings_.views * settings_.peels;
    std::vector<SliceRect> rects(std::size_t(layers) * std::size_t(L), SliceRect{});
    // Per code, the slices that accept it: a layer's rectangles are then unions of per-code boxes.
    std::vector<std::pair<int, int>> accepted(256);
    for (int code = 1; code < 256; ++code) accepted[std::size_t(code)] = acceptedSlices(code, L, settings_.overlap);
    struct Box { int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1; };
    for (int layer = 0; layer < layers; ++layer) {
        Box boxes[256];
        const std::uint8_t* base = texels.data() + std::size_t(layer) * std::size_t(res) * std::size_t(res) * 4u;
        for (int y = 0; y < res; ++y)
            for (int x = 0; x < res; ++x) {
                const int code = base[(std::size_t(y) * std::size_t(res) + std::size_t(x)) * 4u + 3u];
                if (code == 0) continue;
                Box& b = boxes[code];
                b.x0 = std::min(b.x0, x), b.y0 = std::min(b.y0, y), b.x1 = std::max(b.x1, x), b.y1 = std::max(b.y1, y);
            }
        for (int code = 1; code < 256; ++code) {
            const Box& b = boxes[code];
            if (b.x1 < 0) continue;
            for (int s = accepted[std::size_t(code)].first; s <= accepted[std::size_t(code)].second; ++s) {
                SliceRect& r = rects[std::size_t(layer) * std::size_t(L) + std::size_t(s)];
                if (r.empty()) r = {std::uint8_t(b.x0), std::uint8_t(b.y0), std::uint8_t(b.x1), std::uint8_t(b.y1)};
                else r = {std::min(r.x0, std::uint8_t(b.x0)), std::min(r.y0, std::uint8_t(b.y0)),
                          std::max(r.x1, std::uint8_t(b.x1)), std::max(r.y1, std::uint8_t(b.y1))};
            }
        }
    }
    return rects;
}

void LayeredImpostor::buildQuads() {
    const int peels = settings_.peels;
    const float res = float(settings_.resolution);
    std::vector<float> vertices;
    // Level by level, view by view: each view's quads of one level are contiguous.
    for (int levelIndex = 0; levelIndex < levels(); ++levelIndex) {
        Level& level = levels_[std::size_t(levelIndex)];
        const int L = level.slices;
        level.first.assign(level.rects.size(), 0);
        level.count.assign(level.rects.size(), 0);
        level.viewFirst.assign(std::size_t(settings_.views), 0);
        level.viewCount.assign(std::size_t(settings_.views), 0);
        level.quads = 0;
        for (int view = 0; view < settings_.views; ++view) {
            const ImpostorFrame& f = frames_[std::size_t(view)];
            level.viewFirst[std::size_t(view)] = GLint(vertices.size() / kFloatsPerVertex);
            for (int p = 0; p < peels; ++p)
                for (int k = 0; k < L; ++k) {
                    const int s = sliceAt(k, L);
                    const std::size_t i = rangeIndex(view, p, s, levelIndex);
                    const SliceRect r = level.rects[i];
                    if (r.empty()) continue;
                    // Texel x covers u in [x / res, (x + 1) / res).
                    const UvRect uv{{float(r.x0) / res, float(r.y0) / res},
                                    {float(r.x1 + 1) / res, float(r.y1 + 1) / res}};
                    // Peel p's surfaces lie behind peel 0's on every ray (nearer the apex): its quads
                    // sit p quarter-slices nearer the apex, so a pixel's two peels in one slice are
                    // not coplanar fragments (which one-layer-per-depth peeling would merge).
                    const auto q = f.sliceQuad(s, L, uv, -0.25f * float(p));
                    const glm::vec2 c[4] = {uv.min, {uv.max.x, uv.min.y}, uv.max, {uv.min.x, uv.max.y}};
                    level.first[i] = GLint(vertices.size() / kFloatsPerVertex);
                    level.count[i] = kVerticesPerQuad;
                    for (int k : {0, 2, 1, 0, 3, 2})  // counter-clockwise seen from the viewer's side (+axis)
                        vertices.insert(vertices.end(), {q[k].x, q[k].y, q[k].z, c[k].x, c[k].y,
                                                         float(view * peels + p), float(s)});
                    ++level.quads;
                }
            level.viewCount[std::size_t(view)] =
                GLint(vertices.size() / kFloatsPerVertex) - level.viewFirst[std::size_t(view)];
        }
    }
    vertexBytes_ = vertices.size() * sizeof(float);
    quadBuffer_ = gl::Buffer::create();
    glNamedBufferStorage(quadBuffer_.id(), GLsizeiptr(std::max<std::size_t>(vertexBytes_, 4)),
                         vertices.empty() ? nullptr : vertices.data(), 0);
    quadArray_ = makeStandInVertexArray(quadBuffer_.id());
}

void LayeredImpostor::mergeHoleSlices() {
    const Level& fine = levels_[0];
    for (std::size_t l = 1; l < levels_.size(); ++l) {
        Level& level = levels_[l];
        const int merged = fine.slices / level.slices;
        level.holeSlices.clear();
        for (const auto& [pair, slices] : fine.holeSlices) {
            std::set<int> coarse;
            for (int local : slices)
                coarse.insert((local / fine.slices) * level.slices + (local % fine.slices) / merged);
            level.holeSlices[pair] = std::vector<int>(coarse.begin(), coarse.end());
        }
    }
}

void LayeredImpostor::findHoleSlices(const std::vector<BakePart>& parts) {
    // Section 3.3: from the direction halfway between V and an adjacent Vi, draw V's impostor,
    // then Vi's slices with ids where V left pixels empty; the ids in the image are the slices
    // of Vi that close V's holes. Beyond the paper, a hole is also where the mesh itself covers
    // (stencil 1 from a geometry pass, cleared to 0 where V covers): pixels just outside V's
    // silhouette are not holes, and Vi's slices drawn for them would only thicken the rim.
    adjacency_ = adjacentViews(directions_);
    const int res = settings_.resolution, L = settings_.slices, peels = settings_.peels;
    gl::Texture ids = gl::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(ids.id(), 1, GL_R32UI, res, res);
    gl::Texture depthStencil = depthTexture(res, GL_DEPTH24_STENCIL8);
    gl::Framebuffer fbo = gl::Framebuffer::create();
    glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, ids.id(), 0);
    glNamedFramebufferTexture(fbo.id(), GL_DEPTH_STENCIL_ATTACHMENT, depthStencil.id(), 0);
    gl::Program program = gl::buildProgram({"lod/slice_id.vert.glsl", "lod/slice_id.frag.glsl"});
    gl::Program geometry = gl::buildProgram({"lod/bake.vert.glsl", "lod/bake.frag.glsl"});
    const GLint geometryViewProj = glGetUniformLocation(geometry.id(), "uViewProj");
    const GLuint id = program.id();
    glProgramUniform1i(id, glGetUniformLocation(id, "uSlices"), L);
    glProgramUniform1f(id, glGetUniformLocation(id, "uOverlap"), settings_.overlap);
    glProgramUniform1i(id, glGetUniformLocation(id, "uPeels"), peels);
    const GLint viewProjLocation = glGetUniformLocation(id, "uViewProj");

    glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
    glViewport(0, 0, res, res);
    glUseProgram(id);
    glBindVertexArray(quadArray_.id());
    glBindTextureUnit(gpu::BIND_SLICE_ATLAS, atlas_.id());
    glEnable(GL_STENCIL_TEST);
    glStencilMask(0xFF);
    std::vector<GLuint> image(std::size_t(res) * std::size_t(res));
    // A camera at 4 r (a distant object's near-orthographic view) framing the sphere; depth 0
    // at the near plane, nearer wins with LESS.
    const float distance = 4.0f * radius_;
    const glm::mat4 projection = glm::perspectiveRH_ZO(2.0f * std::asin(0.25f), 1.0f, 0.9f * (distance - radius_),
                                                       1.1f * (distance + radius_));
    for (const auto& [v, w] : adjacency_) {
        const glm::vec3 h = glm::normalize(directions_[std::size_t(v)] + directions_[std::size_t(w)]);
        const glm::vec3 hint = std::abs(h.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
        const glm::mat4 viewProj = projection * glm::lookAtRH(centre_ + h * distance, centre_, hint);
        glProgramUniformMatrix4fv(id, viewProjLocation, 1, GL_FALSE, glm::value_ptr(viewProj));
        const GLuint zero = 0;
        const float far = 1.0f;
        glClearNamedFramebufferuiv(fbo.id(), GL_COLOR, 0, &zero);
        glClearNamedFramebufferfi(fbo.id(), GL_DEPTH_STENCIL, 0, far, 0);
        // The mesh: stencil 1 where it covers.
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glDisable(GL_DEPTH_TEST);
        glStencilFunc(GL_ALWAYS, 1, 0xFF);
        glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
        glUseProgram(geometry.id());
        glProgramUniformMatrix4fv(geometry.id(), geometryViewProj, 1, GL_FALSE, glm::value_ptr(viewProj));
        for (const BakePart& part : parts) {
            if (part.indexCount <= 0) continue;
            setPartTransform(geometry.id(), part);
            glBindVertexArray(part.vertexArray);
            glDrawElements(GL_TRIANGLES, part.indexCount, GL_UNSIGNED_INT, nullptr);
        }
        // V: stencil 0 wherever one of its slices accepts a texel.
        glUseProgram(id);
        glBindVertexArray(quadArray_.id());
        glStencilFunc(GL_ALWAYS, 0, 0xFF);
        const Level& fine = levels_[0];
        if (fine.viewCount[std::size_t(v)] > 0) glDrawArrays(GL_TRIANGLES, fine.viewFirst[std::size_t(v)], fine.viewCount[std::size_t(v)]);
        // Vi: ids where V left the stencil clear, nearest slice wins.
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glStencilFunc(GL_EQUAL, 1, 0xFF);
        glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
        if (fine.viewCount[std::size_t(w)] > 0) glDrawArrays(GL_TRIANGLES, fine.viewFirst[std::size_t(w)], fine.viewCount[std::size_t(w)]);
        glGetTextureImage(ids.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, GLsizei(image.size() * sizeof(GLuint)), image.data());
        std::set<int> seen;
        for (GLuint value : image)
            if (value > 0 && value <= GLuint(peels * L)) seen.insert(int(value) - 1);
        levels_[0].holeSlices[{v, w}] = std::vector<int>(seen.begin(), seen.end());
    }
    glBindTextureUnit(gpu::BIND_SLICE_ATLAS, 0);
}

std::pair<GLint, GLsizei> LayeredImpostor::sliceRange(int view, int peel, int slice, int level) const {
    const std::size_t i = rangeIndex(view, peel, slice, level);
    const Level& l = levels_[std::size_t(level)];
    return {l.first[i], l.count[i]};
}

const std::vector<int>& LayeredImpostor::holeSlices(int view, int adjacentView, int level) const {
    static const std::vector<int> none;
    if (!valid()) return none;
    const auto& holes = levels_[std::size_t(level)].holeSlices;
    const auto it = holes.find({view, adjacentView});
    return it == holes.end() ? none : it->second;
}

int LayeredImpostor::nearestView(const glm::vec3& eye) const {
    if (directions_.empty()) return -1;
    const glm::vec3 d = eye - centre_;
    if (!(glm::dot(d, d) > 0.0f)) return 0;
    return nearestViews(directions_, d, 1)[0];
}

float LayeredImpostor::nearestViewAngle(const glm::vec3& eye) const {
    return angleToNearestView(directions_, eye - centre_);
}

StandInDraw LayeredImpostor::drawFor(const glm::vec3& eye, bool fillHoles, int levelIndex) const {
    StandInDraw d;
    if (!valid()) return d;
    levelIndex = std::clamp(levelIndex, 0, levels() - 1);
    const Level& level = levels_[std::size_t(levelIndex)];
    d.vertexArray = quadArray_.id();
    d.atlas = atlas_.id();
    d.albedo = albedo_.id();
    d.slices = level.slices;
    d.overlap = settings_.overlap;
    auto add = [&](GLint first, GLsizei count) {
        if (count <= 0) return;
        if (!d.first.empty() && d.first.back() + d.count.back() == first) d.count.back() += count;
        else { d.first.push_back(first); d.count.push_back(count); }
    };
    const glm::vec3 dir = eye - centre_;
    const std::vector<int> views =
        glm::dot(dir, dir) > 0.0f ? nearestViews(directions_, dir, 3) : std::vector<int>{0};
    add(level.viewFirst[std::size_t(views[0])], level.viewCount[std::size_t(views[0])]);
    if (fillHoles)
        for (std::size_t k = 1; k < views.size(); ++k) {
            // In the buffer's order (sliceAt), so that neighbouring slices join into one range.
            const std::vector<int>& holes = holeSlices(views[0], views[k], levelIndex);
            for (std::size_t h = 0; h < holes.size(); ++h) {
                const int local = frontToBack() ? holes[holes.size() - 1 - h] : holes[h];
                const int peel = local / level.slices, slice = local % level.slices;
                const auto [first, count] = sliceRange(views[k], peel, slice, levelIndex);
                add(first, count);
            }
        }
    return d;
}

ImpostorMemory LayeredImpostor::bytes() const {
    if (!valid()) return {};
    // The albedo atlas, where baked, is a second image per (view, peel) of the same size.
    return {impostorImageBytes(settings_.resolution, settings_.views, settings_.peels) * (albedo_ ? 2u : 1u),
            impostorRectangleBytes(settings_.views, settings_.peels, settings_.slices), vertexBytes_};
}

}  // namespace strata::lod
