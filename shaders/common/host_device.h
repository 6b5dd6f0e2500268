// Makes a header valid C++ and valid GLSL at once (the nvpro samples' pattern), so binding
// points, sizes and struct layouts are written once and host and shaders cannot drift apart.
// C++ sees strata::gpu constexpr values and plain structs, GLSL global constants and structs.
// Shared structs hold scalars only (uint, int, float): those pack alike in C++ and std430,
// vectors do not (vec3 aligns to 16 in std430). tests/gpu_interface_gl_test.cpp checks the
// layouts and the bindings.
// Include guards, not #pragma once: the shader loader inlines every #include it meets.
#ifndef STRATA_HOST_DEVICE_H
#define STRATA_HOST_DEVICE_H

#ifdef __cplusplus
#define GPU_NAMESPACE_BEGIN namespace strata::gpu {
#define GPU_NAMESPACE_END }
#define GPU_CONST inline constexpr
namespace strata::gpu {
using uint = unsigned int;
static_assert(sizeof(uint) == 4 && sizeof(float) == 4, "GLSL's uint and float are 32 bits");
}  // namespace strata::gpu
#else
#define GPU_NAMESPACE_BEGIN
#define GPU_NAMESPACE_END
#define GPU_CONST const
#endif

#endif
