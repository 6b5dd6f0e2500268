// The array-based buffers' fragments (fab, kbuffer, sbuffer) as their shaders see them; the
// storage block lives here, not in buffer_bindings.h, because C++ has no such declaration.
#include "oit/buffers/buffer_bindings.h"

layout(std430, binding = BIND_ENTRIES) coherent buffer FragmentEntries {
    FragmentEntry entries[];
};

// `colorWords` from oit/fragment_color.glsl.
FragmentEntry makeEntry(float depth, uint objectId, uint primitiveId, uvec2 colorWords) {
    return FragmentEntry(depth, objectId, primitiveId, colorWords.x, colorWords.y);
}
