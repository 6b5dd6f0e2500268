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

// Whether a draw of `mesh` with `material` reads the base colour texture: the material has one
// whose image decoded, and the mesh has the TEXCOORD set it names. GpuScene and the reference
// both decide by this.
bool usesBaseColorTexture(const Scene& scene, const Material& material, const Mesh& mesh);

// Linear RGBA of `image` at `uv` (glTF UV: (0, 0) the top-left corner of the image) with the
// sampler's wrap modes and magnification filter, at level 0.
glm::vec4 sampleTexture(const TextureImage& image, const Sampler& sampler, glm::vec2 uv);

// The base colour and alpha of triangle `triangle` of `mesh` at barycentrics (b0, b1, b2):
// factor x texture (if usesBaseColorTexture) x COLOR_0 (if the mesh has it), the product of
// common/shading_model.h's combineBaseColor.
glm::vec4 baseColorAt(const Scene& scene, const Material& material, const Mesh& mesh, std::size_t triangle,
                      const glm::dvec3& barycentrics);

}  // namespace strata
