#pragma once
// Mirrors shaders/common/bindings.glsl: binding points of buffers, images and textures.
namespace strata::bindings {

constexpr unsigned kCounters = 0;
constexpr unsigned kNodes = 1;
constexpr unsigned kHeads = 0;
constexpr unsigned kOpaqueColor = 0;
constexpr unsigned kOpaqueDepth = 1;
constexpr unsigned kResolveOutput = 3;  // image unit: compute resolves write the output colour

}  // namespace strata::bindings
