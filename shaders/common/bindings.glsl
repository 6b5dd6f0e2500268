// Binding points shared by the programs and the host (core/render/bindings.hpp mirrors them;
// change both together). Uniforms are looked up by name.
#define BIND_COUNTERS      0
#define BIND_NODES         1
#define BIND_HEADS         0
#define BIND_OPAQUE_COLOR  0
#define BIND_OPAQUE_DEPTH  1
#define BIND_RESOLVE_OUTPUT 3   // image unit: compute resolves write the output colour
