// Binding points private to the approximate family (core/oit/approximate/approximate_bindings.hpp
// mirrors them; change both together). Kept apart from common/bindings.glsl because nothing
// outside this family reads them; texture unit 0 stays the shared opaque colour.
#define BIND_SAMPLE_DEPTHS   0   // image unit: stochastic per-sample depth bits (r32ui array)
#define BIND_ACCUM           2   // texture unit: accumulation (RGBA32F)
#define BIND_TRANSMITTANCE   3   // texture unit: revealage / total transmittance (R16F, R32F)
