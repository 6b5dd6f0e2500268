// Texture units the peeling family uses beyond the shared ones (shaders/common/bindings.glsl
// owns 0 and 1). core/oit/peeling/peel_bindings.hpp mirrors them; change both together.
#define BIND_PEEL_PREVIOUS  2   // last peeled depth (f2b) or min-max depth (dual, bun range)
#define BIND_PEEL_LAYER     3   // colour of the layer just peeled / front layer / bucket depths
#define BIND_PEEL_BACK      4   // dual: back layer
#define BIND_PEEL_ACCUM     5   // accumulated (colour, transmittance)
#define BIND_PEEL_BACK_ACCUM 6  // dual: back accumulation
#define BIND_BUCKET_COLORS  1   // bun: image unit of the per-slot colours
