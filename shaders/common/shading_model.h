// The shading and material model, written once for the CPU reference (C++, through
// core/render/shading.hpp) and every GPU pass (GLSL, through common/shading.glsl), so the
// reference cannot drift from the GPU. Valid C++ and GLSL at once (common/host_device.h): GLSL
// names (vec3, dot, abs) are glm's in C++, and functions are `GPU_FN`.
#ifndef STRATA_SHADING_MODEL_H
#define STRATA_SHADING_MODEL_H
#include "common/host_device.h"

#ifdef __cplusplus
#include <glm/glm.hpp>
#define GPU_FN inline
namespace strata::gpu {
using glm::abs;
using glm::dot;
using glm::length;
using glm::mix;
using glm::pow;
using glm::vec2;
using glm::vec3;
using glm::vec4;
using glm::mat3;
}  // namespace strata::gpu
#else
#define GPU_FN
#endif

GPU_NAMESPACE_BEGIN

// Two-sided Lambert with an ambient floor, so back faces of transparent objects are lit like
// front faces.
GPU_CONST float kAmbient = 0.3f;

GPU_FN vec3 shadeSurface(vec3 baseColor, vec3 normal, vec3 lightDirection) {
    float len = length(normal);
    float ndl = len > 0.0f ? abs(dot(normal / len, lightDirection)) : 1.0f;
    return baseColor * (kAmbient + (1.0f - kAmbient) * ndl);
}

// The sRGB transfer function's inverse (glTF colour textures; the GL specification's decode for
// SRGB8_ALPHA8 texels, which the GPU applies per texel before filtering).
GPU_FN float srgbToLinear(float c) {
    return c <= 0.04045f ? c / 12.92f : pow((c + 0.055f) / 1.055f, 2.4f);
}

// KHR_texture_transform applied to a TEXCOORD (the matrix is TextureTransform::matrix()).
GPU_FN vec2 transformTexCoord(mat3 transform, vec2 uv) {
    vec3 t = transform * vec3(uv.x, uv.y, 1.0f);
    return vec2(t.x, t.y);
}

// glTF's base colour: factor x texture texel (linear) x COLOR_0, alpha likewise. A material
// without a texture passes (1, 1, 1, 1) for the texel, a mesh without COLOR_0 the same for the
// colour, so the product is the factor alone.
GPU_FN vec4 combineBaseColor(vec4 factor, vec4 texel, vec4 vertexColor) {
    return factor * texel * vertexColor;
}

// MASK: the fragment exists where alpha >= alphaCutoff (glTF 2.0, 3.9.4).
GPU_FN bool alphaMaskKeeps(float alpha, float cutoff) {
    return alpha >= cutoff;
}

GPU_NAMESPACE_END

#endif
