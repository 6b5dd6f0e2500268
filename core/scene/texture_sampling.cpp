#include "scene/texture_sampling.hpp"

#include "common/shading_model.h"

#include <algorithm>
#include <cmath>

namespace strata {
namespace {

// The texel index for a coordinate in texels (a texel's centre at i + 0.5), by the wrap mode
// (OpenGL 4.5, 8.14.2).
int wrapTexel(int i, int size, TextureWrap wrap) {
    switch (wrap) {
    case TextureWrap::ClampToEdge: return std::clamp(i, 0, size - 1);
    case TextureWrap::MirroredRepeat: {
        const int period = 2 * size;
        int m = i % period;
        if (m < 0) m += period;
        return m < size ? m : period - 1 - m;
    }
    case TextureWrap::Repeat:
    default: {
        int m = i % size;
        return m < 0 ? m + size : m;
    }
    }
}

glm::vec4 texel(const TextureImage& image, int x, int y, TexelEncoding encoding) {
    const std::uint8_t* p = image.rgba.data() + (std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 4;
    if (encoding == TexelEncoding::Linear)
        return glm::vec4(float(p[0]), float(p[1]), float(p[2]), float(p[3])) / 255.0f;
    // Colour channels are sRGB-encoded; alpha is linear (glTF 3.9.2).
    return {gpu::srgbToLinear(float(p[0]) / 255.0f), gpu::srgbToLinear(float(p[1]) / 255.0f),
            gpu::srgbToLinear(float(p[2]) / 255.0f), float(p[3]) / 255.0f};
}

// The texel coordinate of a texture coordinate, clamped far outside the image so that the
// integer conversion below stays defined for any float (a wrap of a huge value is still a
// texel of the image; its exact choice there is round-off on any backend).
double texelCoordinate(float uv, int size) {
    return std::clamp(double(uv) * double(size), -1.0e9, 1.0e9);
}

}  // namespace

bool usesTexture(const Scene& scene, const TextureRef& t, const Mesh& mesh) {
    return t.present() && std::size_t(t.image) < scene.images.size() && (t.texCoord == 0 || t.texCoord == 1) &&
           mesh.hasTexCoords(t.texCoord);
}

glm::vec4 sampleTexture(const TextureImage& image, const Sampler& sampler, glm::vec2 uv, TexelEncoding encoding) {
    if (image.width <= 0 || image.height <= 0 || !std::isfinite(uv.x) || !std::isfinite(uv.y))
        return glm::vec4(0.0f);
    const double u = texelCoordinate(uv.x, image.width), v = texelCoordinate(uv.y, image.height);
    const bool nearest = sampler.magFilter == TextureFilter::Nearest;
    if (nearest) {
        const int x = wrapTexel(int(std::floor(u)), image.width, sampler.wrapS);
        const int y = wrapTexel(int(std::floor(v)), image.height, sampler.wrapT);
        return texel(image, x, y, encoding);
    }
    // Bilinear between the four texel centres around (u, v).
    const double fu = u - 0.5, fv = v - 0.5;
    const int x0 = int(std::floor(fu)), y0 = int(std::floor(fv));
    const float a = float(fu - std::floor(fu)), b = float(fv - std::floor(fv));
    const int xs[2] = {wrapTexel(x0, image.width, sampler.wrapS), wrapTexel(x0 + 1, image.width, sampler.wrapS)};
    const int ys[2] = {wrapTexel(y0, image.height, sampler.wrapT), wrapTexel(y0 + 1, image.height, sampler.wrapT)};
    const glm::vec4 top = glm::mix(texel(image, xs[0], ys[0], encoding), texel(image, xs[1], ys[0], encoding), a);
    const glm::vec4 bottom = glm::mix(texel(image, xs[0], ys[1], encoding), texel(image, xs[1], ys[1], encoding), a);
    return glm::mix(top, bottom, b);
}

glm::vec4 textureAt(const Scene& scene, const TextureRef& t, TexelEncoding encoding, const Mesh& mesh,
                    std::size_t triangle, const glm::dvec3& bary) {
    if (!usesTexture(scene, t, mesh)) return glm::vec4(1.0f);
    const std::uint32_t* idx = mesh.indices.data() + 3 * triangle;
    const auto& uvs = mesh.texCoords[t.texCoord];
    const glm::dvec2 uv = bary.x * glm::dvec2(uvs[idx[0]]) + bary.y * glm::dvec2(uvs[idx[1]]) +
                          bary.z * glm::dvec2(uvs[idx[2]]);
    const glm::vec2 transformed = gpu::transformTexCoord(t.transform.matrix(), glm::vec2(uv));
    return sampleTexture(scene.images[std::size_t(t.image)], t.sampler, transformed, encoding);
}

glm::vec4 baseColorAt(const Scene& scene, const Material& material, const Mesh& mesh, std::size_t triangle,
                      const glm::dvec3& bary) {
    const glm::vec4 texelColor = textureAt(scene, material.baseColorTexture, TexelEncoding::Srgb, mesh, triangle, bary);
    glm::vec4 vertexColor(1.0f);
    if (mesh.hasColors()) {
        const std::uint32_t* idx = mesh.indices.data() + 3 * triangle;
        const auto& c = mesh.colors;
        vertexColor = glm::vec4(bary.x * glm::dvec4(c[idx[0]]) + bary.y * glm::dvec4(c[idx[1]]) +
                                bary.z * glm::dvec4(c[idx[2]]));
    }
    return gpu::combineBaseColor(glm::vec4(material.baseColor, material.alpha), texelColor, vertexColor);
}

MaterialPoint materialAt(const Scene& scene, const Material& material, const Mesh& mesh, std::size_t triangle,
                         const glm::dvec3& bary) {
    MaterialPoint p;
    const glm::vec4 mr = textureAt(scene, material.metallicRoughnessTexture, TexelEncoding::Linear, mesh, triangle, bary);
    p.metallic = material.metallic * mr.b;
    p.roughness = material.roughness * mr.g;
    if (usesTexture(scene, material.occlusionTexture, mesh))
        p.occlusion = gpu::occlusionOf(
            textureAt(scene, material.occlusionTexture, TexelEncoding::Linear, mesh, triangle, bary).r,
            material.occlusionStrength);
    p.emissive = material.emissive *
                 glm::vec3(textureAt(scene, material.emissiveTexture, TexelEncoding::Srgb, mesh, triangle, bary));
    return p;
}

}  // namespace strata
