// Binding points of the buffer family (core/oit/buffers/buffer_support.hpp mirrors them; change
// both together). They start above the shared ones in common/bindings.glsl so a program may use
// both sets at once (ll uses the A-buffer's node block at BIND_NODES and heads at BIND_HEADS).
#define BIND_ENTRIES         2   // SSBO: FragmentEntry array (fab, kbuffer, sbuffer)
#define BIND_PIXEL_OFFSETS   3   // SSBO: sbuffer per-pixel counts, scanned in place to offsets
#define BIND_DEPTH_KEYS      4   // SSBO: kbuffer per-pixel sorted depth keys
#define BIND_PIXEL_COUNTS    1   // image unit: fab per-pixel counter (r32ui)
#define BIND_TAIL_ACCUM      2   // texture unit: tail sum(a*c), sum(a)
#define BIND_TAIL_REVEAL     3   // texture unit: tail prod(1-a)
