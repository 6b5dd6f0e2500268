#pragma once
// The CPU side of glTF texturing: which textures a draw uses and what a texture returns at a
// texture coordinate, by the rules the GPU follows (the sampler's wrap modes and magnification
// filter, sRGB decoded per texel before filtering, KHR_texture_transform). The CPU reference
// samples level 0 only: it has no screen-space derivatives to pick a mip level, so where the
// GPU minifies a texture the two differ by the filtering (tests compare where texels are
// magnified, or on constant regions, and state the tolerance).
#include "scene/scene.hpp"

#include <glm/glm.hpp>

namespace strata {

// Whether a draw of `mesh` reads `texture`: the material has it, its image decoded, and the mesh
// has the TEXCOORD set it names. GpuScene and the reference both decide by this.
bool usesTexture(const Scene& scene, const TextureRef& texture, const Mesh& mesh);
inline bool usesBaseColorTexture(const Scene& scene, const Material& material, const Mesh& mesh) {
    return usesTexture(scene, material.baseColorTexture, mesh);
}

// A normal texture bends the normal where the draw reads it and the mesh has tangents (the
// loader derives them where the file has none: scene/tangents.hpp).
inline bool usesNormalTexture(const Scene& scene, const Material& material, const Mesh& mesh) {
    return usesTexture(scene, material.normalTexture, mesh) && mesh.tangents.size() == mesh.positions.size();
}

// How a texture's colour channels are encoded: base colour and emissive textures hold sRGB,
// metallic-roughness, normal and occlusion textures linear values (glTF 3.9). Alpha is linear.
enum class TexelEncoding { Srgb, Linear };

// RGBA of `image` at `uv` (glTF UV: (0, 0) the top-left corner of the image) with the sampler's
// wrap modes and magnification filter, at level 0, decoded to linear values.
glm::vec4 sampleTexture(const TextureImage& image, const Sampler& sampler, glm::vec2 uv,
                        TexelEncoding encoding = TexelEncoding::Srgb);

// `texture` at barycentrics (b0, b1, b2) of triangle `triangle` of `mesh`: its TEXCOORD set
// interpolated, KHR_texture_transform applied, sampled as above; (1, 1, 1, 1), the neutral
// factor, where the draw does not read it (usesTexture).
glm::vec4 textureAt(const Scene& scene, const TextureRef& texture, TexelEncoding encoding, const Mesh& mesh,
                    std::size_t triangle, const glm::dvec3& barycentrics);

// The base colour and alpha of triangle `triangle` of `mesh` at barycentrics (b0, b1, b2):
// factor x texture (if usesBaseColorTexture) x COLOR_0 (if the mesh has it), the product of
// common/shading_model.h's combineBaseColor.
glm::vec4 baseColorAt(const Scene& scene, const Material& material, const Mesh& mesh, std::size_t triangle,
                      const glm::dvec3& barycentrics);

// The rest of a material at a point, as common/material.glsl computes it per fragment:
// metallic and roughness (factors x the texture's blue and green), occlusion (1 without a
// texture) and emission (factor x strength x the sRGB texture).
struct MaterialPoint {
    float metallic = 0.0f;
    float roughness = 1.0f;
    float occlusion = 1.0f;
    glm::vec3 emissive{0.0f};
};
MaterialPoint materialAt(const Scene& scene, const Material& material, const Mesh& mesh, std::size_t triangle,
                         const glm::dvec3& barycentrics);

}  // namespace strata
