// The array-based buffers' fragments (fab, kbuffer, sbuffer) as their shaders see them; the
// storage block lives here, not in buffer_bindings.h, because C++ has no such declaration.
#include "oit/buffers/buffer_bindings.h"

layout(std430, binding = BIND_ENTRIES) coherent buffer FragmentEntries {
    FragmentEntry entries[];
};

FragmentEntry makeEntry(float depth, uint objectId, uint primitiveId, vec4 color) {
    return FragmentEntry(depth, objectId, primitiveId, packHalf2x16(color.rg), packHalf2x16(color.ba));
}
