#pragma once
// Mirrors shaders/oit/peeling/peel_bindings.glsl.
namespace strata::peel_bindings {

constexpr unsigned kPrevious = 2;
constexpr unsigned kLayer = 3;
constexpr unsigned kBack = 4;
constexpr unsigned kAccum = 5;
constexpr unsigned kBackAccum = 6;
constexpr unsigned kBucketColors = 1;  // image unit

}  // namespace strata::peel_bindings
