#pragma once
// Mirrors shaders/oit/approximate/approximate_bindings.glsl (change both together).
namespace strata::approximate_bindings {

constexpr unsigned kSampleDepths = 0;   // image unit
constexpr unsigned kAccum = 2;          // texture unit
constexpr unsigned kTransmittance = 3;  // texture unit

}  // namespace strata::approximate_bindings
